/**
 * The command line's help text (`--help`, and under a usage error): every form, option and column.
 * It names each option as the field registry does (tests/fieldRegistry.test.ts checks it).
 */

import { SURFACE_KINDS } from '../core/surfaces/registry';
import { modeNames } from './registryOptions';

/** The help text of the command line. */
export const USAGE = `Usage: path-interval --R <mm> --Rcr <mm> --rho <deg> [options] --h <mm> [--json] [--simulate]
       path-interval --R <mm> --Rcr <mm> --rho <deg> [options] --ra <mm> [--json] [--simulate]
       path-interval --R <mm> --Rcr <mm> --rho <deg> [options] --interval <mm> [--json] [--simulate]
       path-interval --R <mm> --Rcr <mm> --rho <deg> [options] --flutes <N> --target-sa <mm> [--json]
       path-interval --R <mm> --Rcr <mm> --rho <deg> [options] --flutes <N> --target-rz <mm> [--json]
       path-interval --R <mm> --Rcr <mm> --rho <deg> [options] --half-interval <mm> [--json] [--simulate]
       path-interval --R <mm> --Rcr <mm> --slope <deg> [three-axis options] --h <mm> [--json]
       path-interval --R <mm> --Rcr <mm> --slope <deg> [three-axis options] --horizontal-step <mm> [--json]
       path-interval --R <mm> --Rcr <mm> --slope <deg> --passes waterline [...] --step-down <mm> [--json]
       path-interval --R <mm> --Rcr <mm> --h <mm> --slope-sweep [three-axis options] [--json]
       path-interval --batch [--unit mm|inch] < cases.csv > table.csv

Step-over (path interval L, between adjacent cutter-contact paths) of a filleted (bull-nose)
end mill for a scallop height h or a roughness Ra, exact for any tool posture on a plane or a
cylinder, beside the approximations of Sekine et al., Redonnet et al. and Bedi et al. (Sekine &
Kameya 2022; lead-only models), the osculating circle at the contact and the ball of the corner
radius; with the exact roughness (Rz, Ra, Rq) of the surface the passes leave.

  --R <mm>              tool radius (0.001 to 1000)
  --D <mm>              instead of --R: the tool diameter D = 2R
  --Rcr <mm>            corner radius (0 <= Rcr <= R; Rcr = R is a ball end)
  --rho <deg>           lead angle, along the feed (0 <= rho < 90)
  --tilt <deg>          tilt angle, across the feed; + leans the shank to +Y (-90 < tilt < 90; default 0)
  --pattern <p>         one-way (default) or zigzag (posture mirrored on every other pass)
  --surface-radius <mm> a cylinder: signed radius, > 0 convex, < 0 concave (0.001 <= |Rs| <= 1e6);
                        omitted: a plane. Scallop heights are measured radially, L along the surface
  --surface-axis <a>    feed (default: passes run along the cylinder) or cross (passes go around it)
  --feed-radius <mm>    a doubly curved point: signed principal radius along the feed Rf (> 0
                        convex, < 0 concave; 0.001 <= |Rf| <= 1e6; omitted: straight)
  --cross-radius <mm>   and across the feed Rc. Both: the exact answer at that point beside the
                        plane's, each cylinder's and the usual correction 1/rho = 1/Reff + 1/Rc;
                        one alone is the cylinder shorthand (--cross-radius Rs is --surface-radius
                        Rs --surface-axis feed; --feed-radius Rs, the axis across); not with
                        --surface-radius or --surface-axis
  --h <mm>              scallop height (from 1e-9 up to the flank and shank limits)
  --ra <mm>             instead of --h: the step-over that leaves this roughness Ra (up to the
                        largest Ra the tool leaves, named in the error)
  --interval <mm>       inverse: the scallop height left at step-over L
  --half-interval <mm>  inverse, the step-over given as L/2
  --inverse             optional with --interval or --half-interval (kept for old scripts)
  --simulate            also simulate the passes (the tool solid over a 512 x 512 height field;
                        a plane only) and show its cusp height and roughness beside the exact ones
  --json                print one JSON object instead of a table
  --flutes <N>          the surface the teeth leave (a plane, any lead and tilt): N straight teeth,
  --fz <mm>             each advancing fz (M3); adds the feed-mark height hf along the CC path, its
                        period, the balanced feed fz* (hf = h) and the areal parameters Sa, Sq, Sz,
                        Sp, Sv, Ssk, Sku over one period cell (JSON: feedMarks, areal)
  --feed-rate <mm/min>  with --rpm, instead of --fz: the feed rate F (in/min with --unit inch)
  --rpm <n>             the spindle speed n; they give fz = F / (n z) (not together with --fz)
  --runout <mm>         with --flutes and --fz: radial runout e (default 0; at most R/10)
  --runout-phase <deg>  its direction from tooth 0's half-plane (default 0)
  --pass-phase <q>      each pass shifted along the feed by q (0 <= q < 1) of the feed period
  --target-sa <mm>      with --flutes, on a plane, instead of --h and --fz: the pair (step-over L,
                        feed per tooth fz) whose areal Sa is this, with the largest L x fz (area
                        machined per tooth), and the curve of pairs (JSON: targetSa); a few seconds
  --target-rz <mm>      with --flutes, likewise: the pair with the largest L x fz whose scallop h
                        (across the feed) and feed marks hf (along it) are both at most this: L for
                        h, and its balanced feed fz* (JSON: targetRz)
  --x3p <file>          with --flutes and --fz: write the areal surface as an ISO 25178-72 x3p file
                        (heights in metres on the grid x = (i + 1/2) dx, over whole period cells)
  --x3p-size <nx,ny>    its points along the feed and across (default 1024,1024; at most 8192)
  --x3p-cells <cx,cy>   its period cells along the feed and across (default 1,1)
  --unit <u>            mm (default) or inch: every length in and out in that unit (the table,
                        JSON and the batch; JSON names it in "unit"). Any length may be typed
                        as the shop writes it: a fraction and a unit suffix (1/2", .030in, 5um,
                        1 1/4 in, 0.2 thou, 12.7mm), whatever the unit
  --machine <m>         optional: the machine mode, from the mode registry (${modeNames().join(', ')});
                        3-axis is the slope's (--slope), 5-axis the lead and tilt's
  --surface <kind>      optional: the surface kind, from the surface registry
                        (${SURFACE_KINDS.join(', ')}); it must match the options that give
                        the surface (none of them: a plane)

Three-axis machining (the tool upright, the surface sloped; then --rho and --tilt are not given):
  --slope <deg>         slope alpha of the surface at the contact (0 to 90; at 90 a straight wall
                        is cut flat by the side: no scallop; a concave meridian is answered)
  --passes <p>          raster (default: parallel passes) or waterline (Z-level, along the contour)
  --raster-angle <deg>  raster: plan angle psi of the passes to the fall line (0 to 90; default 0);
                        waterline: 90 or absent (the contour)
  --feed-radius <mm>    waterline only: a surface of revolution about a vertical axis, signed normal
                        radius along the feed (> 0 convex: dome, boss; < 0 concave: bowl, fillet)
  --cross-radius <mm>   waterline only: signed radius of the meridian (signs as --feed-radius);
                        without either radius: a sloped plane
  --h <mm>              the scallop height: gives the programmed step (Lxy or dz), L along the
                        surface and the equivalent lead and tilt
  --interval <mm>       inverse: the cusp height a step-over L along the surface leaves
  --horizontal-step <mm> inverse, raster: the cusp height a horizontal step Lxy leaves
  --step-down <mm>      inverse, waterline: the cusp height a step-down dz (tool tip to tool tip) leaves
  --slope-sweep         instead of --slope, with --h: Lxy (raster) or dz (waterline) for h at 31 slopes
                        from 0 to the largest valid, and the cusp one constant step leaves at each
                        (the flat floor's step for h, or the typed --horizontal-step / --step-down)
  --batch               read CSV on stdin (header R,Rcr,rho and h, Ra or the step-over L;
                        optional tilt, pattern, surfaceRadius, surfaceAxis, or feedRadius,
                        crossRadius; any order; an empty field takes the default;
                        output columns are ignored, so an output or a lookup table reads back;
                        a column may name its unit, R_mm, R_in, rho_deg, as the page's tables do;
                        with --unit inch the lengths of columns that name none are inches),
                        three-axis: a header with slope needs no rho; optional passes,
                        rasterAngle, feedRadius, crossRadius; output interval,horizontalStep,
                        stepDown,lead,tilt,note,error); either with the optional teeth
                        flutes, fz (or feedRate with rpm), runout, runoutPhase, passPhase
                        (output feedMarkHeight,feedPeriod,balancedFz,Sa,Sq,Sz,Sp,Sv,Ssk,Sku),
                        write CSV: the input columns, h (with Ra), then
                        exact,sekine,redonnet,bedi (L/2 of each), interval,halfWidthRight,
                        halfWidthLeft,contactOffset,otherCuspHeight (exact), osculating,
                        cornerBall (L/2), note, error; with L (exact): h,rightCuspHeight,
                        leftCuspHeight,otherCuspHeight,halfWidthRight,halfWidthLeft,
                        contactOffset,note,error;
                        full precision; blank lines skipped
  -h, --help            show this text

Table: 7 significant digits. JSON and CSV: every digit of the double.
Exit codes: 0 success (a batch with bad rows included), 1 a read or write error,
2 invalid input or usage.`;
