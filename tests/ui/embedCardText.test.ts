/** The result card's line of inputs (src/ui/embedCardText.ts), written from the link's state in the state's unit. */
import { describe, expect, it } from 'vitest';
import { cardSummary } from '../../src/ui/embedCardText';
import { parseUrl } from '../../src/ui/state';

/** Each link and the line it gives. */
const CASES: ReadonlyArray<readonly [string, string]> = [
  ['?R=3&Rcr=1&rho=5&h=0.05&unit=mm', 'R 3 mm, Rcr 1 mm, lead 5°, tilt 0°, one-way, plane, h 0.05 mm'],
  [
    '?D=0.5&Rcr=0.03&rho=10&tilt=-4&pattern=zigzag&h=0.0004&unit=in',
    'D 0.5 in, Rcr 0.03 in, lead 10°, tilt -4°, zigzag, plane, h 0.0004 in',
  ],
  [
    '?R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=30&h=0.01&unit=mm',
    'R 3 mm, Rcr 1 mm, 3-axis raster, slope 30°, raster angle 30°, h 0.01 mm',
  ],
  [
    '?R=3&Rcr=1&machine=3axis&passes=waterline&slope=60&h=0.01&unit=mm',
    'R 3 mm, Rcr 1 mm, 3-axis waterline, slope 60°, h 0.01 mm',
  ],
  [
    '?R=3&Rcr=1&rho=5&surfaceRadius=-40&ra=0.002&target=ra&unit=mm',
    'R 3 mm, Rcr 1 mm, lead 5°, tilt 0°, one-way, concave cylinder Rs 40 mm, Ra 0.002 mm',
  ],
  // A target Sa: the card names it (not the h it does not use).
  [
    '?R=3&Rcr=1&rho=5&target=sa&sa=0.0008&z=4&unit=mm',
    'R 3 mm, Rcr 1 mm, lead 5°, tilt 0°, one-way, plane, Sa 0.0008 mm',
  ],
  ['?R=3&Rcr=1&rho=5&mode=inverse&L=2.5&unit=mm', 'R 3 mm, Rcr 1 mm, lead 5°, tilt 0°, one-way, plane, L 2.5 mm'],
];

describe('cardSummary', () => {
  it('names the tool, the posture or the machine, the passes, the surface and the quantity given', () => {
    for (const [query, line] of CASES) expect(cardSummary(parseUrl(query).state), query).toBe(line);
  });
});
