// controls.js: the live estimate (resolution → Z0 nodes/struts → final model size), the advisor's
// warning, time presets, auto threads, and reading the form as RunOptions (on a fake DOM).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { Controls, PRESETS, presetForSeconds, autoThreadCount, estimateText, adviceText } from '../src/controls.js';
import { fakeRoot, setGlobal } from './helpers/fake_dom.mjs';

setGlobal('navigator', { hardwareConcurrency: 3 }); // "auto" threads = 2 in this file

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

test('estimate line: Z0\'s counts, and 2.2–2.9 struts per ball of the final model', () => {
  assert.equal(estimateText({ nodes: 192, struts: 384 }, 192), 'Z0: 192 balls, 384 struts · final ≈ 192 balls, 422–557 struts');
  assert.equal(estimateText({ nodes: 192, struts: 384 }, 1000), 'Z0: 192 balls, 384 struts · final ≈ 1000 balls, 2200–2900 struts');
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

test("the core's default weights (sent at start-up) become the form's", () => {
  const { controls } = makeControls();
  controls.setDefaults({ weights: { dist: 12, surface: 7, unknown: 3, fold: 'x' } });
  const w = controls.get().weights;
  assert.equal(w.dist, 12);
  assert.equal(w.surface, 7);
  assert.equal(w.fold, 1); // not a number: the page's own default stays
  assert.equal(w.unknown, undefined);
  controls.setDefaults({ weights: { dist: 30, surface: 100 } }); // DEFAULTS are module state: put them back
});

test('the form read as RunOptions: defaults, and empty or bad fields fall back', () => {
  const { controls, el } = makeControls();
  assert.deepEqual(controls.get(), { resolution: 12, seconds: 5, target_nodes: 0, threads: 2, seed: 1, proposals: 0,
    initial_only: false, weights: { dist: 30, orient: 100, fair: 5, complex: 1, surface: 100, fold: 1 } });
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
  assert.equal(el('estimate').textContent, 'Z0: 96 balls, 190 struts · final ≈ 100 balls, 220–290 struts');
  assert.equal(el('advice').textContent, "at 8 cells the model's genus is 0, the surface's 1");
  assert.equal(el('advice').hidden, false);
});

test('updateEstimate: a failed estimate (no mesh) clears the line and the old warning, not throws', async () => {
  const { controls, el } = makeControls(async () => { throw new Error('no mesh loaded'); });
  el('estimate').textContent = 'Z0: 96 balls, 190 struts · final ≈ 96 balls, 211–278 struts';
  el('advice').textContent = "at 8 cells the model's genus is 0, the surface's 1";
  el('advice').hidden = false;
  await controls.updateEstimate();
  assert.equal(el('estimate').textContent, '');
  assert.equal(el('advice').textContent, '');
  assert.equal(el('advice').hidden, true);
});
