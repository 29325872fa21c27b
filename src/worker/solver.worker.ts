/** Module Web Worker entry: answers the page's calls with the solver API (workerApi.ts, rpc.ts). */
import { expose } from './rpc';
import { workerApi } from './workerApi';

expose(workerApi, self);
