/**
 * The JavaScript budget of the production build (dist/, built by the browser tests' global
 * set-up), counted as `npm run bench:web` counts it (src/bench/chunks.ts jsSizes): every .js file
 * the build emits, each gzip -9, summed; and the first result's, the page's scripts and the solver
 * worker's with what they import statically. Issue 27 point 2 asks at most 60 kB to the first
 * result and at most 200 kB in all; both are held where they stand, ratchets to lower as the code
 * shrinks. The first result was 62.0 kB until the doubly curved point's models (about 4 kB) left it
 * for first use (src/build/siteSources.ts, the registry's loadSurfaceModel): now 57.96 kB, within the
 * target. In all 236.1 kB before, 212.5 kB now: public/embed.js ships minified
 * (src/build/publicScripts.ts, -2.6 kB), and three.js lost what the page cannot reach
 * (src/build/threeFeatures.ts: render targets, textures other than the DFG table's, the renderer's API
 * beyond what the page calls, serialisation, raycasting, the output pass, uniform buffer objects,
 * other materials' uniform refreshes, dead switches' prefix lines, class methods nothing names;
 * 98.6 -> 77.1 kB); the page's and the core's own code is about 130 kB. Then issue 28's last views
 * and the machine options (+1 kB) and issue 29's surface the teeth leave (+18 kB in all, all of it
 * loaded on first use but its five fields and their seam, +1.1 kB to the first result): 59.5 and
 * 231.9 kB; the finish's faster areal integration (+0.9 kB, on first use) and the teeth-and-feed
 * box as a disclosure (+0.04 kB to the first result): 59.64 and 232.93 kB. Then issue 30's languages:
 * the Japanese and German catalogues and the switch load when used (+4.9 kB in all); what the first
 * result carries of them (the field words, the hook that puts the results into the language in
 * force) is +0.16 kB, less the teaching views' dead 'elsewhere' text: 59.80 and 237.83 kB; with the
 * input errors' words in each (+4 kB, on first use) and the page's one `must`: 59.87 and 241.79 kB;
 * with the question's words, the status lines and the Copy buttons in each language (the words
 * lazy; their lookups in questionWords.ts, copy.ts and resultBar.ts not): 59.95 and 243.29 kB. Then
 * the finish's messages on its fields, the optional fields' link notices and the empty sliders'
 * words (+0.18 kB), less the lookup table's file name and summary, now loaded with its grid on the
 * first click (lookupFile.ts, -0.38 kB): 59.76 and 243.90 kB; the finish box's fixes (on first use): 244.04; runout in
 * the finish core (its worker chunk, on first use, +3.9 kB): 59.78 and 247.91; the finish box's
 * and the tabs' words in each language (on first use): 59.79 and 249.16; the review's fixes (the link's
 * language read at once, the table drawn anew on a switch) less the embed code, now loaded on its
 * first press (-0.28 kB): 59.67 and 249.98; feed rate and spindle speed (two registry fields and
 * their page logic, +0.42 kB), less the lookup table's download, now loaded on its first press as
 * the shop sheet is (lazyButton.ts, in the tools' chunk, -0.48 kB): 59.60 and 251.49; the finish's
 * profiles along and across the feed (core profiles.ts in the finish worker's chunk, their charts with
 * the views' line chart, now a chunk both share; on first use): 59.64 and 252.77; the finish box's
 * one live region and its feed lengths in the unit on screen (on first use): 252.88; a link's fz with
 * F or rpm said in a notice (+0.04 kB): 59.68 and 252.92; the balanced feed set as a feed rate at the
 * spindle speed given (on first use): 59.69 and 253.04.
 * first press (-0.28 kB): 59.67 and 249.98. The shop sheet in Japanese and German (issue 30): its words
 * in each catalogue (+0.9 kB each), its English as one typed words object in the sheet's own chunk,
 * the locale's decimal sign shared with the language code (a chunk of its own, +0.24 kB), all on
 * first use; the first result +0.02 kB (the sheet reads the language in force): 59.68 and 253.05. Then
 * the words the page writes itself (the three-axis step, a flat end's no-scallop line, Copy's spoken
 * confirmation, an empty slider) and eleven more chrome keys in each language, put into the language
 * by language.ts (on first use; copy.ts and fields.ts only hand over, +0.01 kB): 59.69 and 254.28; the
 * three-axis refusals worded from their data in each language (on first use; the hook that hands
 * them over, +0.04 kB): 59.73 and 256.56; the 3D scene's legend in each language (nineteen chrome keys):
 * 59.73 and 257.55; the comparison charts' captions, axis titles, choices and notes in each
 * language (on first use; the tabs' relabel redraws the visible view, a shorter call, -0.01 kB):
 * 59.72 and 259.15; the notices' sentences (a worker restarted or stopped, link values replaced) in
 * each language, put in by language.ts when the page writes the notice (on first use): 59.73 and 260.06;
 * a shop sheet mark's reason in each language from its data (the sheet reads two more of words.ts's
 * exports, +0.01 kB): 59.74 and 260.57; the three-axis chart "step against slope" in each language
 * (on first use): 59.74 and 261.94; a doubly curved point's charts of L against each radius in each
 * language (on first use): 59.74 and 262.66; the views' lines over a page question in each language
 * (on first use): 59.74 and 263.64. The first result has 13 bytes left under its ratchet.
 * Then the teeth's surface in 3D in the Machined surface view (on first use, +1.75 kB: the view +0.8,
 * the finish worker's map of several cells +0.38, the shared seam +0.17, its ja and de words +0.35).
 * kB here are 1024 bytes, as bench:web prints them.
 *
 * The four branches of 7 December merged (the page validating fields only, the language leftovers, the
 * target Sa on the page, the teeth's surface in 3D): 60.60 and 274.01 kB. The first result is 0.6 kB
 * over its 60 kB target again (each branch fitted alone; together the page's target-Sa choice, the
 * three-axis refusals' hook and the worker's slider limits add up): the ratchet is raised to hold
 * the line, and the target is said not met.
 *
 * The Machined surface view and the finish box's worker messages in Japanese and German (issue 30,
 * on first use only: the first result unchanged): each language's catalogue +1.3 kB, the finish box
 * +0.78 (its English sentences and the wording of the worker's data), the views +0.45, the worker's
 * data +0.09: 277.93 in all. The ratchet is raised to 278.0.
 * Then the 3D scene's labels and name in each language (its own words moved to render/sceneWords.ts,
 * the page's labels put into the language by the catalogue: the first result +0.04 kB, 60.64; the
 * scene +0.26, each catalogue +0.14, the language pass +0.06): 278.77 in all, the ratchet 278.8.
 * Then the cross-feed profile's words in each language (on first use: each catalogue +0.75 kB, the
 * views +0.42; the first result 60.64): 280.67 in all, the ratchet 280.7.
 * Then the procedures' names on the page in each language (the table's head and rows put into the
 * language by language.ts, the charts' and the profile's legends by the views, all on first use;
 * each catalogue +0.35 kB; the first result 60.64): 281.61 in all, the ratchet 281.7.
 * Then the target-Sa box's worker messages in each language (the worker names its refusals and sends
 * the teeth's data; the box words them with the finish box's finishText.ts, on first use): 282.17 in
 * all, the ratchet 282.2.
 * Then a doubly curved point's refusals in each language (curvedText.ts and each catalogue's words,
 * on first use; the page's hook in request.ts paid for by one return in curvedRequest.ts: the first
 * result 60.64): 283.36 in all, the ratchet 283.4. Then a doubly curved point's comparison rows'
 * names in each language (language.ts, on first use): 283.64, the ratchet 283.7.
 * Then the step-through's steps, the formulas' words and the paper's tables in each language, and the
 * procedures' table's name and rows' title (all on first use; the first result 60.63): the Japanese
 * catalogue +2.9 kB and the German +2.7 (the assumptions of six procedures, the tables' two notes and
 * the step captions are long text), the views +1.0 (their English as typed words objects, the tables
 * built again in another language), language.ts +0.07: 290.29 in all, the ratchet raised to 290.3 by
 * that cost.
 * Then a curved radius field's own messages, a worker's reason for a restart and the procedures'
 * table's own name in each language (each catalogue +0.2 kB; workerReason.ts a chunk of its own,
 * +0.28, shared by language.ts, the finish box and the target-Sa box, +0.15 in their chunks; all on
 * first use); the radius field's
 * hook in the first result (+0.04 kB) paid for by the procedures' table box's name, focus and role
 * moved from results.ts into index.html: the first result 60.62, 291.17 in all, the ratchet 291.2.
 * Then a link notice's details in each language (linkNotices.ts reads the page's English back, in
 * the language code's chunk, +0.66 kB; each catalogue +0.4; on first use; the first result 60.62):
 * 292.64 in all, the ratchet 292.7.
 * Then a chart gap's reason and the simulation's reason for an exception in each language (the
 * views read the core's English back, gapReasons.ts and surfaceWords.ts, +0.58 kB with the English
 * sentences they read against; each catalogue +0.42; on first use; the first result 60.62): 294.06
 * in all, the ratchet 294.1.
 * Then the landmarks' names, the roughness's rule of thumb (and its note on a surface of revolution)
 * and L's share of the tool diameter in each language (put in by language.ts from the page's
 * English, on first use; the first result +0.01 kB: roughness.ts's note is read by the language chunk, 60.63):
 * 294.74 in all, the ratchet 294.8.
 * Then the catalogue tools' names (the preset box, the chips' titles and legend) in each language
 * (toolNames.ts and its pass in language.ts, each catalogue's words; on first use; the first result
 * 60.62): 295.21 in all, the ratchet 295.3.
 * Then the 3D scene's heights' scale badge and its title in each language (its English moved from
 * scene.ts to render/sceneWords.ts, in the scene's chunk; the words in each catalogue; +0.27 kB in
 * all, on first use; the first result 60.63): 295.48 in all, the ratchet 295.5.
 * Then the balanced feed's closed form and the feed marks' crest and tip searches (the finish
 * worker's chunk, on first use, +0.56 kB): 296.04 in all, the ratchet 296.1.
 * Then the last of the page's words in Japanese and German (issue 30): the procedures' table's notes
 * (tableNotes.ts in the language chunk, which reads the models' reasons with the chart's
 * gapReasons.ts, now a chunk of its own shared with the views, +0.53 kB), the rows' hover titles,
 * n/a, the surface presets, the presentation mode's buttons, the tab list's name and the lookup
 * table's restart line (the language chunk +1.72 kB, each catalogue +1.3); the presentation mode's
 * buttons now hold both their words in index.html, shown by present.css, so present.ts writes none:
 * the first result 60.63 -> 60.57 kB; 301.02 in all. Then the lookup table's computing and saved
 * lines in each language (lookupFile.ts words the summary, on first use; each catalogue +0.2 kB):
 * 301.52 in all, the ratchet 301.6.
 * Then three-axis machining's page builder and wording on first use (app.ts loads threeAxisRequest.ts
 * with the first three-axis question; the core's three-axis validation goes with it, -1.1 kB, less
 * the chunk Rolldown splits off for format.ts, which both then import), and a dynamic import no
 * longer lists the chunks its importer loaded already (src/build/preloadDeps.ts, -0.04 kB): the
 * first result 59.52 kB, within its 60 kB target again, the ratchet 59.55; 296.66 in all (the split
 * chunk's own compression), the ratchet 296.7. Both together: the first result 59.41 kB, the ratchet
 * 59.45; 301.98 in all, the ratchet 302.0.
 * Then what the step-over means and what L and the heights mean on a cylinder or at a doubly
 * curved point in each language (meaningWords.ts in the language chunk, each catalogue's words; on
 * first use), less the scene drawables' one dispose (-0.04 kB): the first result 59.40, 302.83 in all,
 * the ratchet 302.9.
 * Then the worker's doubly curved and three-axis jobs ask the registries (issue 27 point 3: the
 * sloped plane's refusals apart from its solve, question.ts posturedModel, the page job's `ready`;
 * +0.55 kB in the jobs' and the later chunk, on first use), and no preload list in a chunk the worker
 * also runs (preloadDeps.ts: the core chunk's, whose helper touched the worker's missing document,
 * -0.12 kB): the first result 59.40 -> 59.38 kB; 302.83 -> 303.32 in all. With the feed marks'
 * searches inside each piece of a line and the bounded runout search (the finish worker's chunk, on
 * first use, +0.9 kB): 304.23 in all, the ratchet 304.3. Then the pass's crest and peak kept by one
 * memo and the sloped plane checked once, its answer built field by field (later chunks, +0.11 kB):
 * 304.33 in all, the ratchet 304.4. Then the surface of revolution's gouging check takes its clipped
 * tool as one object (a duplicates pair gone; the three-axis chunk, on first use, +0.08 kB): 304.41
 * in all, the ratchet 304.5. Then the finish fields' text checked on its fields apart from the
 * question (the first result 59.32), and every message's quote of an entry with its control and
 * invisible characters escaped (core/input/visibleText.ts, the command line's escapes moved into the
 * core: a "3" + BEL no longer reads as a valid "3"): the first result 59.49 kB, the ratchet 59.5, still
 * under the 60 kB target; 304.57 in all, the ratchet 304.6. Then the runout line's bites followed by
 * Newton, the moments started from the mean's panels and the highest point searched again about the
 * integral's lines (core/finish, in the later chunk the finish workers load, on first use, +1.41
 * kB): 306.00 in all, the ratchet 306.1. Then the audit's language leftovers in each language (a
 * radius's side box, the link's text box, the cylinder rows' heading, "h for this Ra": each
 * catalogue's words and language.ts's pass, on first use, +0.29 kB); then the copy-link and embed-code buttons' status in each language (four phrases in each catalogue
 * and language.ts's pass, on first use; copyLink.ts hands it over, the first result +0.02 kB, 59.40),
 * less the charts' decimal sign now set once in lineChart.ts (-0.02); then three-axis machining's "a target Ra or Sa is not offered" in each language (threeAxisRequest.ts
 * and each catalogue, on first use, +0.1 kB), with the finish fields' own message worded in the
 * language in force (pageMessages.ts hands in describeError): the first result 59.51 kB, the ratchet
 * 59.55 (under the 60 kB target); 306.87 in all. Then the doubly curved point answered through its model everywhere and its flank's
 * height read below the top (the doubly curved chunk, on first use, +0.12 kB; the first result +0.05): the first result 59.57 kB,
 * the ratchet 59.6 (under the 60 kB target); 307.01 in all. Then the flank's far-side height by its own
 * bisection (the doubly curved chunk, on first use, +0.11 kB): the first result 59.59, 307.12 in all, the
 * ratchet 307.2.
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { jsSizes } from '../../src/bench/chunks';
import { gzip9, siteFiles } from '../../src/bench/siteFiles';

const DIST = fileURLToPath(new URL('../../dist', import.meta.url));
const KB = 1024;

describe('the JavaScript budget of the built site', () => {
  const sizes = jsSizes(siteFiles(DIST), readFileSync(`${DIST}/index.html`, 'utf8'), gzip9);

  it('the first result (page and worker, their static imports) is at most 59.6 kB gzip (the ratchet, under the 60 kB target)', () => {
    expect(sizes.firstResult.some((p) => p.startsWith('assets/index-'))).toBe(true);
    expect(sizes.firstResult.some((p) => p.startsWith('assets/solver.worker-'))).toBe(true);
    expect(sizes.firstResultGzip / KB, sizes.firstResult.join(', ')).toBeLessThanOrEqual(59.6);
  });

  it('counts every .js file the build emits: the chunks, the service worker and embed.js', () => {
    const emitted = [...siteFiles(DIST).keys()].filter((p) => p.endsWith('.js'));
    expect(emitted).toEqual(expect.arrayContaining(['sw.js', 'embed.js']));
    expect(sizes.files).toBe(emitted.length);
  });

  it('all of it, every .js file, is at most 307.2 kB gzip (the ratchet; the target is 200)', () => {
    expect(sizes.totalGzip / KB).toBeLessThanOrEqual(307.2);
  });
});
