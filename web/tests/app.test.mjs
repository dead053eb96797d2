// app.js with a scripted bridge and recording viewer/controls: a failure (bad file, bad link,
// failed run, unreachable URL) becomes one status line and never replaces the model on screen;
// successes update the name, the summary and the parts.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { App, qualityText, qualityTechText, placesText, plainFidelity, resultText, verdictText } from '../src/app.js';
import { Event } from '../src/protocol.js';
import { Status } from '../src/status.js';
import { FakeElement, fakeDocument, setGlobal } from './helpers/fake_dom.mjs';

const warnings = [];
console.warn = (...args) => warnings.push(args.join(' ')); // Status.error logs; keep the output clean

function makeApp(bridgeOverrides = {}) {
  const listeners = {};
  const bridge = {
    on: (type, fn) => (listeners[type] ??= []).push(fn),
    emit: (type, data) => (listeners[type] || []).forEach((fn) => fn(data)),
    calls: [],
    load: async (name) => { bridge.calls.push(['load', name]); return { kind: 'mesh', report: { vertices: 8, faces: 12, genus: 0 } }; },
    surface: async () => ({ positions: new Float32Array(9), triangles: new Uint32Array([0, 1, 2]) }),
    parts: async () => ({ balls: 5 }),
    summary: async () => ({ balls: 5, struts: 4, by_kind: { B0: 2, Y0: 1, R0: 1 }, valid: true, genus: 0 }),
    run: async (options) => { bridge.calls.push(['run', options]); return { state: 'done', seconds: 1.5, note: '' }; },
    openLink: async () => ({ kind: 'model' }),
    ...bridgeOverrides,
  };
  const viewer = { models: [], surfaces: [], setModel(s, o) { this.models.push(o); }, setSurface(s) { this.surfaces.push(s); } };
  const controls = { sets: [], running: [], estimates: 0, set(o) { this.sets.push(o); }, get: () => ({ seconds: 5, seed: 3 }),
    setRunning(r) { this.running.push(r); }, scheduleEstimate() { this.estimates++; } };
  const plot = { resets: 0, reset() { this.resets++; }, update() {} };
  const parts = { shown: 0, cleared: 0, show() { this.shown++; }, clear() { this.cleared++; } };
  const statusEl = new FakeElement('div'), summaryEl = new FakeElement('div'), surfaceEl = new FakeElement('div');
  const app = new App({ bridge, viewer, controls, plot, parts, status: new Status(statusEl), summaryEl, surfaceEl });
  return { app, bridge, viewer, controls, plot, parts, statusEl, summaryEl, surfaceEl };
}

/** A bridge whose load shows a model the way the worker does: the snapshot event, then the reply. */
const modelLoad = (bridge) => async () => {
  bridge.emit(Event.SNAPSHOT, { snapshot: { version: 1 } });
  return { kind: 'model' };
};

test('a model file: its snapshot is framed, later ones are not; name, summary and parts follow', async () => {
  const t = makeApp();
  t.bridge.load = modelLoad(t.bridge);
  assert.deepEqual(await t.app.loadBytes('torus.zome.json', new ArrayBuffer(1)), { kind: 'model' });
  t.bridge.emit(Event.SNAPSHOT, { snapshot: { version: 2 } }); // e.g. the next run's progress
  assert.deepEqual(t.viewer.models, [{ fit: true }, { fit: false }]);
  assert.equal(t.app.currentName, 'torus');
  assert.equal(t.statusEl.textContent, 'torus.zome.json: model loaded.');
  assert.equal(t.summaryEl.textContent, '5 balls, 4 struts (B0 2, Y0 1, R0 1) · a closed surface');
  assert.equal(t.parts.shown, 1);
});

test('a VEF\'s notes follow "model loaded" on the status line, each a sentence', async () => {
  const t = makeApp();
  t.bridge.load = async () => ({ kind: 'model', notes: ['1 strut end has no ball in the file (vZome draws none there)'] });
  await t.app.loadBytes('part.vef', new ArrayBuffer(1));
  assert.equal(t.statusEl.textContent,
    'part.vef: model loaded. 1 strut end has no ball in the file (vZome draws none there).');
});

test('quality line: the fidelity sentence of a run, and whether the parts fit side by side', () => {
  assert.equal(qualityText({}), '');
  assert.equal(qualityText({ clashes: 0, clearance: 'no clashes: the closest parts are two struts 2.3 mm apart' }),
    'Buildable: no clashes: the closest parts are two struts 2.3 mm apart.');
  assert.equal(qualityText({ clashes: 4, clearance: '4 clashes: 4 pairs of balls too close' }),
    'Cannot be built as it is: 4 clashes: 4 pairs of balls too close.');
  assert.equal(qualityText({ stats: { fidelity: { summary: 'largest gap 24 mm (0.52 b0), where the model misses the surface, at the top' } },
    clashes: 0, clearance: 'no clashes: x' }),
  'Largest gap 24 mm, where the model misses the surface, at the top. Buildable: no clashes: x.');
  assert.equal(plainFidelity('largest gap 20 mm (0.43 b0), at the back; typical distance 5.3 mm (RMS 0.113 b0)'),
    'largest gap 20 mm, at the back; typical distance 5.3 mm');
  assert.equal(qualityTechText({ valid: true, genus: 1, stats: { fidelity: { summary: 'largest gap 20 mm (0.43 b0)' } } }),
    'Valid Zome surface, genus 1. Largest gap 20 mm (0.43 b0).');
  assert.equal(qualityTechText({ valid: false, validation: 'open at 2 edges' }), 'Not a valid Zome surface: open at 2 edges.');
  assert.equal(qualityTechText({}), '');
  assert.equal(qualityText({ stats: { fold_overs: 2 } }), '2 faces are turned inside out (fold-overs).');
  assert.equal(qualityText({ stats: { fold_overs: 0 } }), '');
  // Where they are, grouped as the core's CLI line groups them (core/score/fold_over_report.h).
  assert.equal(qualityText({ stats: { fold_overs: 3, fold_over_places: [
    { where: 'left', at: [0, 0, 0] }, { where: 'top left', at: [0, 1, 0] }, { where: 'left', at: [1, 0, 0] }] } }),
  '3 faces are turned inside out (fold-overs), 2 at the left, at the top left.');
  assert.equal(placesText([{ where: 'middle' }]), 'in the middle');
  assert.equal(placesText(undefined), '');
});

test('a mesh: its surface and diagnosis are shown and the estimate refreshed', async () => {
  const t = makeApp();
  t.bridge.load = async () => ({ kind: 'mesh', report: { vertices: 8, faces: 12, genus: 1, repaired: ['merged 2 vertices'] } });
  await t.app.loadBytes('ring.OBJ', new ArrayBuffer(1));
  assert.equal(t.surfaceEl.textContent, 'ring.OBJ: 8 vertices, 12 triangles, 1 hole through it (repaired: merged 2 vertices)');
  assert.equal(t.viewer.surfaces.length, 1);
  assert.equal(t.controls.estimates, 1);
  assert.equal(t.app.currentName, 'ring');
});

test('a file the core refuses: one red line naming the file, and the model on screen stays', async () => {
  const t = makeApp();
  t.bridge.load = modelLoad(t.bridge);
  await t.app.loadBytes('torus.zome.json', new ArrayBuffer(1));
  t.bridge.load = async () => { throw new Error('the file is empty'); };
  const result = await t.app.loadBytes('empty.obj', new ArrayBuffer(0));
  assert.deepEqual(result, { ok: false, error: 'empty.obj: the file is empty' });
  assert.equal(t.statusEl.textContent, 'empty.obj: the file is empty');
  assert.equal(t.statusEl.className, 'status error');
  assert.equal(t.app.lastError, 'empty.obj: the file is empty');
  assert.equal(t.app.currentName, 'torus'); // downloads keep the shown model's name
  assert.equal(t.viewer.models.length, 1);
  assert.equal(t.viewer.surfaces.length, 0);
  t.bridge.load = async () => { throw new Error('bad.ply: list length out of range'); };
  assert.equal((await t.app.loadBytes('bad.ply', new ArrayBuffer(1))).error, 'bad.ply: list length out of range'); // not "bad.ply: bad.ply: …"
});

test('a refused file does not leave the next model\'s framing switched on', async () => {
  const t = makeApp();
  t.bridge.load = modelLoad(t.bridge);
  await t.app.loadBytes('torus.zome.json', new ArrayBuffer(1));
  t.bridge.load = async () => { throw new Error('not a mesh'); };
  await t.app.loadBytes('x.obj', new ArrayBuffer(1), { fit: true });
  t.bridge.emit(Event.SNAPSHOT, { snapshot: { version: 2 } });
  assert.deepEqual(t.viewer.models.at(-1), { fit: false });
});

test('a file dropped during a run is not lost: it waits, is announced, and loads when the run ends', async () => {
  let finish;
  const t = makeApp({ run: () => new Promise((resolve) => { finish = resolve; }) });
  const running = t.app.run();
  const result = await t.app.loadBytes('next.obj', new ArrayBuffer(1), { run: false });
  assert.deepEqual(result, { ok: true, queued: true });
  assert.deepEqual(t.bridge.calls, []); // not sent to the core while it runs
  assert.equal(t.statusEl.textContent, 'next.obj will load when this run ends (Cancel to load it now).');
  finish({ state: 'done', seconds: 1, note: '' });
  await running;
  await t.app.afterQueued;
  assert.deepEqual(t.bridge.calls, [['load', 'next.obj']]);
  // The run's own line stays, the load follows it (issue 38: the cancel message no longer vanished).
  assert.equal(t.statusEl.textContent, 'Finished in 1.0 s. 5 balls, buildable. next.obj loaded.');
});

test('a waiting file runs only if "run after loading" is ticked when it loads; the end is said at once', async () => {
  let finish;
  const t = makeApp({ run: () => new Promise((resolve) => { finish = resolve; }) });
  let autorun = true;
  const running = t.app.run();
  await t.app.loadBytes('next.obj', new ArrayBuffer(1), { run: () => autorun });
  autorun = false; // unticked while the file waited
  const lines = [];
  t.controls.setRunning = (r) => { if (!r) queueMicrotask(() => lines.push(t.statusEl.textContent)); };
  finish({ state: 'cancelled', seconds: 2, nodes: 5, note: '' });
  await running;
  await t.app.afterQueued;
  assert.equal(lines[0], 'Cancelled; kept the best model in 2.0 s. Reading the parts…'); // not "Running…"
  assert.deepEqual(t.bridge.calls, [['load', 'next.obj']]); // loaded, not run
  assert.equal(t.app.runCount, 1);
  assert.match(t.statusEl.textContent, /^Cancelled; kept the best model in 2\.0 s\..* next\.obj loaded\.$/);
});

test('result line and verdict in plain words: a lost hole is flagged, clashes are named', () => {
  const s = { balls: 256, struts: 600, by_kind: { B0: 600 }, valid: true, genus: 0, clashes: 0,
    stats: { fidelity: { hausdorff_mm: 31.4 } } };
  assert.equal(resultText(s, 1), '256 balls, 600 struts (B0 600) · Warning: the shape has 1 hole through it, ' +
    'this model has no hole (the note under the resolution says why).');
  assert.equal(resultText(s, 1, -1), '256 balls, 600 struts (B0 600) · Warning: the shape has 1 hole through it, ' +
    'this model has no hole.');
  assert.equal(resultText({ ...s, genus: 1 }, 1), "256 balls, 600 struts (B0 600) · a closed surface with the shape's holes");
  assert.equal(resultText(s, null), '256 balls, 600 struts (B0 600) · a closed surface');
  assert.equal(resultText({ ...s, valid: false, validation: 'open at 2 edges' }),
    '256 balls, 600 struts (B0 600) · Not a closed Zome surface: open at 2 edges');
  assert.equal(verdictText({ ...s, genus: 1 }, 1), '256 balls, largest gap 31 mm, buildable');
  assert.equal(verdictText(s, 1), '256 balls, largest gap 31 mm, buildable, but it has no hole through it where the shape ' +
    'has 1 hole (the note under the resolution says why)');
  assert.equal(resultText(s, 1, 10), '256 balls, 600 struts (B0 600) · Warning: the shape has 1 hole through it, ' +
    'this model has no hole (try 10 cells).');
  assert.equal(verdictText(s, 1, 10), '256 balls, largest gap 31 mm, buildable, but it has no hole through it where the ' +
    'shape has 1 hole (try 10 cells)');
  assert.equal(verdictText({ ...s, clashes: 2, stats: {} }, null), '256 balls, cannot be built as it is (parts clash)');
});

test('a new mesh is drawn at once and the old model\'s results are cleared', async () => {
  const t = makeApp();
  t.summaryEl.textContent = 'old model';
  await t.app.loadBytes('ring.obj', new ArrayBuffer(1));
  assert.equal(t.parts.cleared, 1);
  assert.equal(t.plot.resets, 1);
  assert.match(t.summaryEl.textContent, /made before this shape was loaded/);
});

test('a bad share link: "share link: …", the model stays; a good one is named shared-model', async () => {
  const t = makeApp({ openLink: async () => { throw new Error('not a share link (no m=1.…)'); } });
  assert.deepEqual(await t.app.openLink('#q=1'), { ok: false, error: 'share link: not a share link (no m=1.…)' });
  assert.equal(t.statusEl.className, 'status error');
  assert.equal(t.app.currentName, 'model');
  assert.equal(t.parts.shown, 0);
  t.bridge.openLink = async () => ({ kind: 'model' });
  assert.deepEqual(await t.app.openLink('#m=1.AB'), { ok: true });
  assert.equal(t.app.currentName, 'shared-model');
  assert.equal(t.app.lastError, null);
});

test('a run gets the controls\' options; the end is reported with time and note', async () => {
  const t = makeApp();
  t.bridge.run = async (o) => { t.bridge.calls.push(['run', o]); return { state: 'done', seconds: 1.54, note: 'target reached' }; };
  const final = await t.app.run({ seed: 3 });
  assert.deepEqual(t.controls.sets, [{ seed: 3 }]);
  assert.deepEqual(t.bridge.calls, [['run', { seconds: 5, seed: 3 }]]);
  assert.equal(final.state, 'done');
  assert.equal(t.statusEl.textContent, 'Finished in 1.5 s. 5 balls, buildable. Target reached.');
  assert.deepEqual(t.controls.running, [true, false]);
  assert.equal(t.app.runCount, 1);
  t.bridge.run = async () => ({ state: 'cancelled', seconds: 2, note: '' });
  await t.app.run();
  assert.equal(t.statusEl.textContent, 'Cancelled; kept the best model in 2.0 s. 5 balls, buildable.');
});

test('a failed run: "run: …", the page is idle again and the kept model\'s results refreshed', async () => {
  const t = makeApp({ run: async () => { throw new Error('out of memory'); } });
  const final = await t.app.run();
  assert.deepEqual(final, { state: 'failed', error: 'out of memory' });
  assert.equal(t.statusEl.textContent, 'run: out of memory');
  assert.equal(t.app.running, false);
  assert.deepEqual(t.controls.running, [true, false]);
  assert.equal(t.parts.shown, 1);
  await assert.rejects(async () => { t.app.running = true; await t.app.run(); }, { message: 'a run is in progress' });
});

test('results that cannot be read clear the panel instead of throwing; an invalid model says so', async () => {
  const t = makeApp({ parts: async () => { throw new Error('no model'); } });
  t.summaryEl.textContent = 'stale';
  await t.app.refreshResults();
  assert.equal(t.parts.cleared, 1);
  assert.equal(t.summaryEl.textContent, '');
  t.bridge.parts = async () => ({});
  t.bridge.summary = async () => ({ balls: 3, struts: 3, by_kind: { B0: 3 }, valid: false });
  await t.app.refreshResults();
  assert.equal(t.summaryEl.textContent, '3 balls, 3 struts (B0 3) · Not a closed Zome surface');
});

test('loadUrl: an unreachable URL is one status line; an odd %-escape in its name does not throw', async () => {
  const restoreDocument = setGlobal('document', fakeDocument());
  const restoreFetch = setGlobal('fetch', async () => ({ ok: false, status: 404 }));
  try {
    const t = makeApp();
    assert.deepEqual(await t.app.loadUrl('samples/missing.obj'),
      { ok: false, error: 'missing.obj: could not fetch it (samples/missing.obj: HTTP 404)' });
    const odd = await t.app.loadUrl('samples/50%off.obj'); // decodeURIComponent('50%off.obj') throws
    assert.equal(odd.error, '50%off.obj: could not fetch it (samples/50%off.obj: HTTP 404)');
    assert.equal(t.viewer.models.length, 0);
  } finally {
    restoreDocument();
    restoreFetch();
  }
});

test('a run that lost the shape\'s hole names a resolution that keeps it, asked of the core', async () => {
  const t = makeApp();
  t.bridge.load = async () => ({ kind: 'mesh', report: { vertices: 8, faces: 12, genus: 1 } });
  const asked = [];
  t.bridge.estimate = async (r) => { asked.push(r); return { kept: false, advice_resolution: 12 }; };
  t.bridge.run = async () => ({ state: 'done', seconds: 2, nodes: 20, note: '' });
  t.controls.get = () => ({ resolution: 6, seconds: 1 });
  await t.app.loadBytes('ring.obj', new ArrayBuffer(1), { chooseResolution: false });
  await t.app.run();
  assert.deepEqual(asked, [6]);
  assert.match(t.summaryEl.textContent, /this model has no hole \(try 12 cells\)\.$/);
  assert.match(t.statusEl.textContent, /but it has no hole through it where the shape has 1 hole \(try 12 cells\)\.$/);
  // A run stopped before it made a model (nodes 0) leaves the old model, which is not compared.
  t.bridge.load = async () => ({ kind: 'mesh', report: { vertices: 8, faces: 12, genus: 1 } });
  await t.app.loadBytes('other.obj', new ArrayBuffer(1), { chooseResolution: false });
  t.bridge.run = async () => ({ state: 'cancelled', seconds: 0.3, nodes: 0, note: '' });
  await t.app.run();
  assert.deepEqual(asked, [6]);
  assert.equal(t.summaryEl.textContent, '5 balls, 4 struts (B0 2, Y0 1, R0 1) · a closed surface');
  assert.equal(t.statusEl.textContent, 'Cancelled; kept the best model in 0.3 s. 5 balls, buildable.');
});

test('a sample: its finished model, then its mesh; the result line compares their holes', async () => {
  const t = makeApp();
  t.bridge.load = async (name) => (name.endsWith('.zome.json') ? { kind: 'model' }
    : { kind: 'mesh', report: { vertices: 8, faces: 12, genus: 0 } });
  const bytes = Promise.resolve(new ArrayBuffer(1));
  await t.app.showSample('torus', { sample: { id: 'torus', mesh: 'torus.obj', label: 'Torus', credit: 'x', resolution: 8 },
    mesh: bytes, model: bytes });
  assert.equal(t.summaryEl.textContent, "5 balls, 4 struts (B0 2, Y0 1, R0 1) · a closed surface with the shape's holes");
  assert.equal(t.bridge.calls.length, 0); // no run: the finished model is shown
});

test('an open sheet is refused with "Give it a thickness", which loads the same bytes again as a slab', async () => {
  const t = makeApp();
  t.statusEl.ownerDocument = fakeDocument();
  const loads = [];
  t.bridge.load = async (name, bytes, options) => {
    loads.push({ name, size: bytes.byteLength, thicken: options?.thicken });
    if (!options?.thicken) {
      throw new Error('mesh is an open sheet, not a solid: its open edge (4 boundary edges) runs around it');
    }
    return { kind: 'mesh', report: { vertices: 8, faces: 12, genus: 0, repaired: ['gave the open sheet a thickness'] } };
  };
  const first = await t.app.loadBytes('terrain.obj', new ArrayBuffer(7), { chooseResolution: false });
  assert.equal(first.ok, false);
  const button = t.statusEl.children.find((c) => c.tagName === 'BUTTON');
  assert.ok(button, 'the refusal offers a button');
  assert.equal(button.textContent, 'Give it a thickness');
  button.dispatch('click');
  await new Promise((resolve) => setTimeout(resolve, 0));
  assert.deepEqual(loads, [{ name: 'terrain.obj', size: 7, thicken: false }, { name: 'terrain.obj', size: 7, thicken: true }]);
  assert.match(t.surfaceEl.textContent, /repaired: gave the open sheet a thickness/);
  // Any other refusal offers nothing.
  t.bridge.load = async () => { throw new Error('mesh has no faces'); };
  await t.app.loadBytes('cloud.obj', new ArrayBuffer(3));
  assert.equal(t.statusEl.children.length, 0);
});

test('quality: a mirrored model says it maps onto itself; a shape not symmetric says why', () => {
  const used = { stats: { mirror: { mode: 'auto', used: true, axis: 'z', at: 0, model: { symmetric: true } } } };
  assert.equal(qualityText(used), 'Mirror-symmetric (about a plane across the z axis): every ball and strut has its mirror image.');
  const refused = { stats: { mirror: { mode: 'auto', used: false, message: 'Not made mirror-symmetric: the shape is lopsided.' } } };
  assert.equal(qualityText(refused), 'Not made mirror-symmetric: the shape is lopsided.');
  assert.equal(qualityText({ stats: { mirror: { mode: 'off', message: '' } } }), '');
});

test('the mirror plane: drawn for a symmetric model with its view option, gone for the next shape and during a run', async () => {
  const planes = [];
  const t = makeApp({ parts: async () => ({ balls: 5, mirror: { axis: 'z', coordinate_b0: 4.85, half: {}, middle: {} } }) });
  t.viewer.setMirrorPlane = (p) => planes.push(p);
  const option = new FakeElement('label');
  option.hidden = true;
  t.app.mirrorOptionEl = option;
  await t.app.refreshResults();
  assert.deepEqual(planes.at(-1), { axis: 2, at: 4.85 });
  assert.equal(option.hidden, false);
  await t.app.loadBytes('ring.obj', new ArrayBuffer(1)); // a new shape: the old model's plane goes
  assert.equal(planes.at(-1), null);
  assert.equal(option.hidden, true);
  await t.app.refreshResults();
  t.bridge.parts = async () => ({ balls: 5 }); // the next run's model is not symmetric
  await t.app.run();
  assert.ok(planes.includes(null));
  assert.equal(planes.at(-1), null);
  assert.equal(option.hidden, true);
});
