/** Page entry: styles and the calculator. */
import './ui/style.css';
import { CalculatorApp } from './ui/app';

const root = document.getElementById('app');
if (root) new CalculatorApp(root);
