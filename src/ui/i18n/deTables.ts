/**
 * The paper's tables view in German (issue 30): its notes, captions, head and the names of its
 * boxes and rows, in the terms of de.ts (Studie, Schnitt, einziger Kontakt, exakt); the column
 * symbols and the paper's numbers kept. Part of de.ts.
 */
import type { TableWords } from './teachWords';

export const DE_TABLES: TableWords = {
  note: 'Jede Zelle: gedruckt / neu berechnet, in mm wie in der Studie (in beiden Einheiten). Hervorgehoben: Der neu berechnete Wert rundet nicht auf die gedruckten Ziffern. Die Tabellen 4-5 werten Gl. 12-13 beim gedruckten 3D-L/2 aus, wie die Studie. Eine Bedingung anklicken, um sie in den Rechner zu laden.',
  why: 'Warum die gedruckte 3D-Spalte 0.0005-0.013 mm zu niedrig ist: Abbildung 1 der Studie lässt zwei Dinge offen, ob eta aus Gl. 2 normiert ist und wie weit die Suche der Schritte 15-16 läuft, und ihr Suchbereich kann knapp vor dem wahren Maximum enden. Eine plausible Lesart (Gl. 2 wie gedruckt, der Bereich vom Schnitt des einzigen Kontakts bis zum Winkel seines P_hp) ergibt die gedruckten 1.879 mm für R = 3, Rcr = 1, rho = 5, h = 0.10, wo das wahre Maximum 1.892 mm ist. Die exakten Werte hier stimmen mit einer dichten Abtastung der Torusfläche und mit dem eigenen Verfahren der Studie bis zur Konvergenz überein (die Schritt-für-Schritt-Ansicht), sind also nicht auf die gedruckte Spalte abgestimmt.',
  halfCaption: 'Tabellen 2-3: L/2 [mm] für h',
  heightCaption: 'Tabellen 4-5: h [mm] beim gedruckten 3D-L/2',
  halfName: 'Tabellen 2-3',
  heightName: 'Tabellen 4-5',
  region: (name) => `${name} (seitlich scrollbar, wenn breiter als der Bildschirm)`,
  table: 'Tabelle',
  printedHalf: 'L/2 (3D) [mm]',
  load: 'Diese Bedingung in den Rechner laden',
};
