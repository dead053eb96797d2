// controls.js: the live estimate (resolution → Z0 nodes/struts → final model size), the advisor's
// warning, time presets, auto threads, and reading the form as RunOptions (on a fake DOM).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { Controls, PRESETS, presetForSeconds, autoThreadCount, estimateText, adviceText, billText, sizeText, isLarge,
  kitsText, setupSeconds, setupText, SETUP, mirrorText }
  from '../src/controls.js';
import { fakeRoot, fakeDocument, setGlobal } from './helpers/fake_dom.mjs';

setGlobal('navigator', { hardwareConcurrency: 3 }); // "auto" threads = 2 in this file
setGlobal('document', fakeDocument()); // the advice's button and consent box are made with it

/** Controls on a fake form; the estimate calls are recorded and answered by `answer`. */
function makeControls(answer = async (r) => ({ nodes: 10 * r, struts: 20 * r, kept: true })) {
  const root = fakeRoot();
  const calls = [];
  const controls = new Controls(root, { estimate: (r) => { calls.push(r); return answer(r); } });
  clearTimeout(controls.estimateTimer); // the tests call updateEstimate themselves
  controls.maxThreads = 4;
  const el = (id) => root.querySelector('#' + id);
  return { controls, el, calls };
}

test('estimate line: balls, 2.2–2.9 struts per ball, size at real scale and kits', () => {
  const e = { nodes: 192, struts: 384, size_mm: 898, kits: 2, kit_plan: '1 Creator 3 + 1 Basic' };
  assert.equal(estimateText(e, 192),
    'The model: ≈ 192 balls, 422–557 struts, 90 cm across, kits: 1 Creator 3 + 1 Basic (the run keeps within them)');
  assert.equal(billText({ nodes: 8124, size_mm: 3293 }), '≈ 8124 balls, 17873–23560 struts, 3.3 m across');
  assert.equal(sizeText(1234), '1.2 m');
  assert.equal(isLarge({ nodes: 8124, size_mm: 3293 }), true);
  assert.equal(isLarge({ nodes: 600, size_mm: 1100 }), false);
  assert.equal(isLarge({ nodes: 600, size_mm: 2500 }), true);
});

test('advice: nothing when Z0 keeps the genus; the advisor\'s text, or the genus mismatch spelled out', () => {
  assert.equal(adviceText({ kept: true, advice: 'ignored', genus: 0, surface_genus: 1 }, 8), '');
  assert.equal(adviceText({ kept: false, advice: 'raise the resolution to 14', genus: 0, surface_genus: 1 }, 8),
    'raise the resolution to 14');
  assert.equal(adviceText({ kept: false, advice: '', genus: 0, surface_genus: 1 }, 8),
    "at 8 cells the model's genus is 0, the surface's 1");
});

test('presets: seconds map back to their preset, anything else is custom; the page offers the same', () => {
  assert.deepEqual([5, 30, 120, 31, 0].map(presetForSeconds), ['quick', 'standard', 'thorough', 'custom', 'custom']);
  const html = readFileSync(new URL('../index.html', import.meta.url), 'utf8');
  for (const [name, seconds] of Object.entries(PRESETS)) {
    const label = html.match(new RegExp(`<option value="${name}">${name} \\(([^)]*)\\)`))[1];
    assert.equal(label, seconds >= 60 ? `${seconds / 60} min` : `${seconds} s`, name);
  }
});

test('auto threads: all cores but one, at least 1, at most the build\'s maximum', () => {
  assert.equal(autoThreadCount(8, 4), 4);
  assert.equal(autoThreadCount(4, 4), 3);
  assert.equal(autoThreadCount(2, 4), 1);
  assert.equal(autoThreadCount(1, 4), 1);
  assert.equal(autoThreadCount(undefined, 4), 1); // unknown core count counts as 2
  assert.equal(autoThreadCount(16, 1), 1); // single-threaded build
});

test("the core's run settings (sent at start-up) become the form's defaults and bounds", () => {
  const { controls, el } = makeControls();
  el('resolution').value = '17';
  controls.setSchema({ defaults: { resolution: 0, seconds: 120, seed: 3, weights: { dist: 12, surface: 7, unknown: 3,
    fold: 'x' } }, bounds: { resolution: { min: 2, max: 256 }, seconds: { min: 0.1, max: 604800 },
    'weights.dist': { min: 0, max: 1e6 } }, presets: { quick: 5, standard: 30, thorough: 120 } });
  const o = controls.get();
  assert.equal(o.weights.dist, 12);
  assert.equal(o.weights.surface, 7);
  assert.equal(o.weights.fold, 1); // not a number: the page's own default stays
  assert.equal(o.weights.unknown, undefined);
  assert.equal(o.seconds, 120);
  assert.equal(el('preset').value, 'thorough');
  assert.equal(o.seed, 3);
  assert.equal(o.resolution, 17); // "automatic" is chosen per mesh, not a slider position
  assert.equal(el('resolution').min, '2');
  assert.equal(el('resolution').max, '256');
  assert.equal(el('seconds').max, '604800');
  assert.equal(el('w-dist').max, '1000000');
  // DEFAULTS are module state: put them back.
  controls.setSchema({ defaults: { seconds: 30, seed: 1, weights: { dist: 30, surface: 100 } } });
  clearTimeout(controls.estimateTimer);
});

test('automatic choice: grid and ball target set with its message; a lost genus needs consent unless none keeps it', async () => {
  const { controls, el } = makeControls(async (r) => ({ nodes: 10 * r, struts: 20 * r, kept: r >= 14, genus: 0,
    surface_genus: 1, advice: r < 14 ? `at ${r} cells the handle of this shape closes up; 14 keeps it` : '',
    advice_resolution: r < 14 ? 14 : 0, size_mm: r * 75, kits: 1, kit_plan: '1 Creator 3' }));
  const a = await controls.chooseAutomatically(async () => ({ resolution: 14, nodes: 528, struts: 1056, kept: true,
    genus: 1, surface_genus: 1, target_nodes: 950, message: '14 cells (528 balls, aiming at 950; about 1.07 m): the ' +
    'grid nearest the default 10 that keeps the hole through it (none from 6 to 13 cells does)',
    size_mm: 1070, kits: 1, kit_plan: '1 Creator 3' }));
  clearTimeout(controls.estimateTimer);
  assert.equal(a.resolution, 14);
  assert.equal(el('resolution').value, '14');
  assert.equal(Number(el('target').value), 950); // the annealer is asked for more balls than Z0 holds
  assert.equal(controls.get().target_nodes, 950);
  assert.match(el('estimate').textContent, /^Resolution chosen for this shape: 14 cells \(528 balls, aiming at 950/);
  assert.match(el('estimate').textContent, /The model: ≈ 950 balls/);
  assert.equal(controls.runBlocker(), '');
  // The user moves the slider to 8: the choice's target goes with it; the estimate knows the
  // handle closes; the run waits for consent.
  controls.set({ resolution: 8 });
  clearTimeout(controls.estimateTimer);
  assert.equal(controls.get().target_nodes, 0);
  await controls.updateEstimate();
  assert.equal(el('estimate').textContent.startsWith('Resolution chosen'), false);
  assert.match(controls.runBlocker(), /closes up; 14 keeps it/);
  const button = el('advice').children.find((c) => c.id === 'use-advice');
  assert.ok(button, 'the suggestion is a button');
  await new Promise((resolve) => setTimeout(resolve, 0));
  assert.match(button.textContent, /^Use 14 cells \(≈ 140 balls/);
  const consent = el('advice').children.find((c) => c.tagName === 'LABEL').children[0];
  consent.checked = true;
  consent.dispatch('change');
  assert.equal(controls.runBlocker(), '');
  button.dispatch('click');
  clearTimeout(controls.estimateTimer);
  assert.equal(el('resolution').value, '14');
  // No grid keeps the genus: the choice says so and the run goes on without asking.
  await controls.chooseAutomatically(async () => ({ resolution: 12, nodes: 600, kept: false, genus: 0,
    surface_genus: 1, message: 'no grid from 6 to 32 cells keeps the hole through it', size_mm: 900 }));
  clearTimeout(controls.estimateTimer);
  assert.equal(controls.runBlocker(), '');
  // Said once, as the warning; nothing to tick (issue 38: no "run anyway" box is ticked for the user).
  assert.match(el('advice').text, /no grid from 6 to 32 cells/);
  assert.doesNotMatch(el('estimate').textContent, /no grid from 6 to 32 cells/);
  assert.equal(el('advice').children.some((c) => c.tagName === 'LABEL'), false);
  assert.equal(el('advice').hidden, false);
  // A target the user typed stays when the slider moves, and when the next mesh is chosen for.
  controls.set({ target_nodes: 700 });
  controls.set({ resolution: 9 });
  clearTimeout(controls.estimateTimer);
  assert.equal(controls.get().target_nodes, 700);
  await controls.chooseAutomatically(async () => ({ resolution: 8, nodes: 210, kept: true, genus: 0, surface_genus: 0,
    target_nodes: 378, message: '8 cells (210 balls, aiming at 378; about 62 cm): the default size', size_mm: 620 }));
  clearTimeout(controls.estimateTimer);
  assert.equal(controls.get().resolution, 8);
  assert.equal(controls.get().target_nodes, 700);
  // A built size the user asked for stays when a mesh is dropped: no automatic grid then.
  controls.set({ size_cm: 50 });
  let asked = false;
  assert.equal(await controls.chooseAutomatically(async () => { asked = true; return { resolution: 11 }; }), null);
  clearTimeout(controls.estimateTimer);
  assert.equal(asked, false);
  assert.equal(controls.get().size_cm, 50);
  assert.equal(controls.get().resolution, 8);
});

test('kits before a run: the core\'s range, the kits the run keeps within last; one plan when both ends agree', () => {
  assert.equal(kitsText({ kit_plan: '2 Creator 3', kit_plan_low: '1 Creator 3 + 1 Basic' }),
    'about 1 Creator 3 + 1 Basic to 2 Creator 3 (the run keeps within them)');
  assert.equal(kitsText({ kit_plan: '1 Creator 3', kit_plan_low: '1 Creator 3' }), '1 Creator 3 (the run keeps within them)');
  assert.equal(kitsText({ kit_plan: '' }), '');
});

test('the time a preset does not count: from the estimate\'s starting model, then from the last run', () => {
  assert.equal(setupSeconds({ z0_seconds: 0.5 }), SETUP.perZ0 * 0.5 + SETUP.fixed);
  assert.equal(setupSeconds({ z0_seconds: 0.5 }, 3.2), 3.2);
  assert.equal(setupSeconds(null), 0);
  assert.equal(setupText(2.2), 'Plus about 2.5 s to build the starting model and measure the result.');
  assert.equal(setupText(12.1, true), 'Plus about 13 s to build the starting model and measure the result (the last run).');
  assert.equal(setupText(0), '');
});

test('a shown result of this shape and resolution is the one kit sentence; a new shape clears the line', async () => {
  const { controls, el } = makeControls(async (r) => ({ nodes: 10 * r, struts: 20 * r, kept: true, genus: 1,
    surface_genus: 1, size_mm: r * 75, kits: 1, kit_plan: '1 Creator 3' }));
  el('resolution').value = '12';
  await controls.updateEstimate();
  assert.match(el('estimate').textContent, /kits: 1 Creator 3 \(the run keeps within them\)/);
  controls.setResult(12);
  assert.equal(el('estimate').textContent, 'The model on screen was made at 12 cells; its parts and kit plan are under Parts.');
  el('resolution').value = '14'; // another resolution: another model, with its own estimate
  await controls.updateEstimate();
  assert.match(el('estimate').textContent, /kits: 1 Creator 3 \(the run keeps within them\)/);
  controls.shapeChanged();
  assert.equal(el('estimate').textContent, 'Choosing a resolution for this shape…');
  assert.equal(controls.lastEstimate, null);
  clearTimeout(controls.estimateTimer);
});

test('the form read as RunOptions: defaults, and empty or bad fields fall back', () => {
  const { controls, el } = makeControls();
  assert.deepEqual(controls.get(), { resolution: 12, seconds: 30, target_nodes: 0, threads: 2, seed: 1, proposals: 0,
    initial_only: false, size_cm: 0, mirror: 'off',
    weights: { dist: 30, orient: 100, fair: 5, complex: 1, surface: 100, fold: 1 } });
  el('seed').value = '';
  el('w-fair').value = 'abc';
  el('threads').value = '9'; // more than the build has
  assert.equal(controls.get().seed, 1);
  assert.equal(controls.get().weights.fair, 5);
  assert.equal(controls.get().threads, 4);
});

test('set(): seconds pick the matching preset or "custom" (then the field is editable)', () => {
  const { controls, el } = makeControls();
  controls.set({ seconds: 30 });
  assert.equal(el('preset').value, 'standard');
  assert.equal(el('seconds').disabled, true);
  controls.set({ seconds: 17, target_nodes: 500, weights: { orient: 50 } });
  assert.equal(el('preset').value, 'custom');
  assert.equal(el('seconds').disabled, false);
  assert.equal(controls.get().seconds, 17);
  assert.equal(controls.get().target_nodes, 500);
  assert.equal(controls.get().weights.orient, 50);
  controls.set({ preset: 'thorough' });
  assert.equal(controls.get().seconds, 120);
  clearTimeout(controls.estimateTimer);
});

test('updateEstimate: uses the target when set, shows the advice, and a stale answer never wins', async () => {
  let release;
  const slow = new Promise((resolve) => { release = resolve; });
  const answers = [() => slow, async () => ({ nodes: 96, struts: 190, kept: false, genus: 0, surface_genus: 1, advice: '' })];
  const { controls, el, calls } = makeControls(() => answers[calls.length - 1]());
  el('resolution').value = '6';
  const first = controls.updateEstimate();
  el('resolution').value = '8';
  el('target').value = '100';
  await controls.updateEstimate();
  release({ nodes: 1, struts: 1, kept: true }); // the answer for resolution 6 arrives last
  await first;
  assert.deepEqual(calls, [6, 8]);
  assert.equal(el('estimate').textContent, 'The model: ≈ 100 balls, 220–290 struts');
  assert.equal(el('advice').text, "at 8 cells the model's genus is 0, the surface's 1.  run anyway");
  assert.equal(el('advice').hidden, false);
});

test('updateEstimate: a failed estimate (no mesh) clears the line and the old warning, not throws', async () => {
  const { controls, el } = makeControls(async () => { throw new Error('no mesh loaded'); });
  el('estimate').textContent = 'Z0: 96 balls, 190 struts · final ≈ 96 balls, 211–278 struts';
  el('advice').textContent = "at 8 cells the model's genus is 0, the surface's 1";
  el('advice').hidden = false;
  await controls.updateEstimate();
  assert.equal(el('estimate').textContent, '');
  assert.equal(el('advice').text, '');
  assert.equal(el('advice').hidden, true);
});

test('mirror: the switch follows the core\'s judgement of the shape until the person sets it', () => {
  const { controls, el } = makeControls();
  const symmetric = { mode: 'auto', symmetric: true, axis: 'x', at: 0, rms_mm: 0.47, max_mm: 5.6 };
  const lopsided = { mode: 'auto', symmetric: false, message: 'Not made mirror-symmetric: the shape\'s best mirror plane (normal 0.04, 0.15, 0.99) is not perpendicular to an axis of the mesh.' };
  assert.equal(mirrorText(symmetric),
    'The shape is mirror-symmetric to within 0.5 mm (about a plane across its x axis): the model is built symmetric, both halves with the same parts.');
  assert.match(mirrorText({ ...symmetric, rms_mm: 0.01 }), /mirror-symmetric exactly/);
  assert.equal(mirrorText(lopsided), lopsided.message);
  controls.showMirror(symmetric);
  assert.equal(el('mirror-row').hidden, false);
  assert.equal(el('mirror').checked, true);
  assert.equal(controls.get().mirror, 'auto');
  controls.showMirror(lopsided);
  assert.equal(el('mirror').checked, false);
  assert.equal(controls.get().mirror, 'off');
  assert.equal(el('mirror-note').textContent, lopsided.message);
  controls.set({ mirror: 'auto' }); // the person (or a script) chose: a new estimate keeps it
  controls.showMirror(lopsided);
  assert.equal(controls.get().mirror, 'auto');
  controls.shapeChanged(); // a new shape: the switch is the core's again
  assert.equal(el('mirror-row').hidden, true);
  controls.showMirror(lopsided);
  assert.equal(controls.get().mirror, 'off');
});

test('a shape put up in steps: one estimate after it, without kits beside its model, with them elsewhere', async () => {
  const root = fakeRoot();
  const calls = [];
  const controls = new Controls(root, {
    estimate: async (r, target, opts) => {
      calls.push({ r, kits: opts?.kits });
      return opts?.kits === false ? { nodes: 10 * r, struts: 20 * r, kept: true }
        : { nodes: 10 * r, struts: 20 * r, kept: true, kit_plan: '1 Creator 3', kit_plan_low: '' };
    },
  });
  clearTimeout(controls.estimateTimer);
  await controls.holdEstimates(async () => {
    controls.set({ resolution: 6 }); // a step in between: no estimate for it
    controls.set({ resolution: 8 });
    controls.setResult(8); // the model on screen was made at 8 cells
    await new Promise((resolve) => setTimeout(resolve, 250)); // past the estimate's 200 ms debounce
    assert.deepEqual(calls, [], 'no estimate while held');
  });
  await new Promise((resolve) => setTimeout(resolve, 0));
  assert.deepEqual(calls, [{ r: 8, kits: false }]);
  assert.match(root.querySelector('#estimate').textContent, /made at 8 cells/);
  // Another resolution names kits: the line's estimate is asked with them.
  controls.set({ resolution: 10 });
  await new Promise((resolve) => setTimeout(resolve, 250));
  assert.deepEqual(calls.at(-1), { r: 10, kits: true });
  assert.match(root.querySelector('#estimate').textContent, /kits: 1 Creator 3/);
  // Back beside the model, then away from it with the kit-less answer on record: asked again with kits.
  controls.showEstimate({ nodes: 80, struts: 160, kept: true }, 8);
  controls.setResult(0);
  await new Promise((resolve) => setTimeout(resolve, 250));
  assert.deepEqual(calls.at(-1), { r: 10, kits: true });
  clearTimeout(controls.estimateTimer);
});
