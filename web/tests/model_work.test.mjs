// model_work.js: the steps on the model on screen (Improve, Fewer balls, More detail, Fix the
// largest gap) send the core a continued run at its own size, and Undo loads the model before the
// last step back (on a fake DOM, with a scripted app and bridge).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { ModelWork, stepTarget, gapSpot, stepText, capacityFull } from '../src/model_work.js';
import { fakeRoot } from './helpers/fake_dom.mjs';

const summary = (balls, gap) => ({ balls, valid: true,
  stats: { b1_mesh_units: 0.2, fidelity: { hausdorff_mm: gap, largest_gap: { at: [1, 2, 3] } } } });

const MORE_TITLE = 'The same size with 30% more balls, at most as many as the shape holds well at that size';

function scripted() {
  const runs = [], loads = [];
  const app = { shownSummary: summary(400, 50), modelOfSurface: true, running: false,
    async run(options, extra) {
      runs.push(extra);
      this.shownSummary = summary(extra.target_nodes || 401, 40);
      return { state: 'done', nodes: this.shownSummary.balls };
    },
    async refreshResults() { this.shownSummary = summary(400, 50); } };
  const bridge = { exportModel: async () => ({ bytes: new Uint8Array([1, 2, 3]) }),
    load: async (name, bytes) => { loads.push({ name, bytes }); return { kind: 'model' }; } };
  const root = fakeRoot();
  root.querySelector('#work-more').title = MORE_TITLE; // as in index.html
  return { work: new ModelWork(root, { app, bridge }), app, runs, loads, el: (id) => root.querySelector('#' + id) };
}

test('ball targets: −25 % and +30 % of the model, the same for Improve, at least 4', () => {
  assert.equal(stepTarget('fewer', 400), 300);
  assert.equal(stepTarget('more', 400), 520);
  assert.equal(stepTarget('improve', 400), 400);
  assert.equal(stepTarget('fewer', 4), 4);
});

test('the spot a fix changes: the largest gap, within three B1 lengths; none without figures', () => {
  assert.deepEqual(gapSpot(summary(400, 50)), { near: [1, 2, 3], radius: 0.6000000000000001 });
  assert.equal(gapSpot({ stats: {} }), null);
  assert.match(stepText('Fewer balls', summary(400, 50), summary(300, 61)),
    /^Fewer balls: 400 → 300 balls, largest gap 50 mm → 61 mm\. Undo/);
  const stuck = { ...summary(190, 70), stats: { ...summary(190, 70).stats,
    continued: { short_of_target: true, target_nodes: 142 } } };
  assert.match(stepText('Fewer balls', summary(196, 70), stuck), /it reached 190 of the 142 balls asked/);
});

test('a step continues the model on screen; Undo loads the one before it', async () => {
  const { work, app, runs, loads, el } = scripted();
  assert.equal(el('work-fewer').disabled, false);
  assert.equal(el('work-undo').disabled, true);
  await work.step('fewer');
  assert.deepEqual(runs[0], { continue: true, target_nodes: 300 });
  assert.equal(app.shownSummary.balls, 300);
  assert.equal(el('work-undo').disabled, false);
  assert.match(el('work-note').textContent, /400 → 300 balls/);
  await work.step('fix');
  assert.deepEqual(runs[1], { continue: true, target_nodes: 0, near: [1, 2, 3], radius: 0.6000000000000001 });
  assert.equal(el('work-here').disabled, true); // no spot chosen yet
  work.setSpot([4, 5, 6]);
  assert.equal(el('work-here').disabled, false);
  assert.match(el('work-note').textContent, /^Spot chosen: Fix here changes only the model within about 22 cm/);
  await work.step('here');
  assert.deepEqual(runs[2], { continue: true, target_nodes: 0, near: [4, 5, 6], radius: 0.6000000000000001 });
  await work.undo();
  await work.undo();
  await work.undo();
  assert.equal(loads.length, 3);
  assert.deepEqual([...new Uint8Array(loads[0].bytes)], [1, 2, 3]);
  assert.equal(el('work-undo').disabled, true);
  assert.equal(app.modelOfSurface, true);
});

test('no steps while a run goes, on a model of another shape, or on an invalid one', () => {
  const { work, app, el } = scripted();
  app.running = true;
  work.refresh();
  assert.equal(el('work-improve').disabled, true);
  app.running = false;
  app.modelOfSurface = false;
  work.refresh();
  assert.equal(el('work-more').disabled, true);
  assert.match(el('work-note').textContent, /drop the mesh it was made from, then the model/);
  app.modelAfterMesh = true; // a saved model dropped after its mesh
  work.refresh();
  assert.equal(el('work-more').disabled, false);
  assert.equal(el('work-note').textContent, '');
  app.modelAfterMesh = false;
  app.modelOfSurface = true;
  app.shownSummary = { ...summary(10, 5), valid: false };
  work.refresh();
  assert.equal(el('work-fix').disabled, true);
});

test('More detail at the surface\'s capacity: off, and the core\'s sentence says why', async () => {
  const { work, app, runs, el } = scripted();
  assert.equal(el('work-more').disabled, false);
  const full = 'the model has 520 balls and at this size the surface holds about 500 well; more would crumple ' +
    'the model (the paper\'s fold-overs): for more detail choose a larger size (a new run)';
  assert.match(capacityFull({ capacity: 500, capacity_full: full }), /^The model has 520 balls .* \(a new run\)\.$/);
  assert.equal(capacityFull({ capacity: 500 }), '');
  app.shownSummary = { ...summary(520, 40), capacity: 500, capacity_full: full };
  work.refresh();
  assert.equal(el('work-more').disabled, true);
  assert.equal(el('work-fewer').disabled, false);
  assert.equal(el('work-improve').disabled, false);
  assert.match(el('work-more').title, /^The model has 520 balls and at this size the surface holds about 500 well/);
  assert.match(el('work-note').textContent, /^The model has 520 balls/);
  assert.equal(await work.step('more'), null); // through the API too: no run, the same sentence
  assert.match(el('work-note').textContent, /^The model has 520 balls/);
  assert.equal(runs.length, 0);
  app.shownSummary = { ...summary(380, 40), capacity: 500 }; // after Fewer balls, or Undo
  work.refresh();
  assert.equal(el('work-more').disabled, false);
  assert.equal(el('work-more').title, MORE_TITLE);
  assert.equal(el('work-note').textContent, '');
});

test('a More detail step the core capped at the capacity says so in the core\'s words', () => {
  const note = 'At this size the surface holds about 500 balls well; more would crumple the model (the paper\'s ' +
    'fold-overs): the target was kept at 500. For more detail choose a larger size (a new run).';
  const after = { ...summary(497, 40), stats: { ...summary(497, 40).stats,
    continued: { capped: true, capacity: 500, target_nodes: 500, capacity_note: note } } };
  assert.equal(stepText('More detail', summary(420, 50), after),
    `More detail: 420 → 497 balls, largest gap 50 mm → 40 mm. ${note} Undo puts the previous model back.`);
});
