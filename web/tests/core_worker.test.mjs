// The worker protocol end to end in one process: CoreBridge (the page's side) talks to the real
// worker/core_worker.js, whose wasm module is replaced by fixtures/fake_wasm/. Checks that every
// request gets exactly one reply, that failures arrive as Errors with the core's own one-line
// message, and the ordering the page relies on. The tests share the worker's state and run in order.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { CoreBridge } from '../src/bridge.js';
import { Event } from '../src/protocol.js';

const posted = []; // every message the worker posted, in order: {msg, transfer}
const bridge = new CoreBridge();
globalThis.self = {
  postMessage(msg, transfer = []) {
    posted.push({ msg, transfer });
    bridge.receive(msg);
  },
};
await import('../src/worker/core_worker.js');
const sent = []; // transfer lists the page handed over
bridge.worker = {
  postMessage(msg, transfer = []) {
    sent.push(transfer);
    self.onmessage({ data: msg });
  },
};
// What the fake core's runSettingsSchema() says: init hands it over, with its defaults.
const SCHEMA_JSON = { defaults: { resolution: 0, weights: { dist: 30, surface: 100 } },
  bounds: { resolution: { min: 2, max: 256 } }, presets: { standard: 30 } };
const SCHEMA = { defaults: SCHEMA_JSON.defaults, schema: SCHEMA_JSON };
const fatal = [];
bridge.on(Event.FATAL, (e) => fatal.push(e.error));
const snapshots = [];
bridge.on(Event.SNAPSHOT, ({ snapshot }) => snapshots.push(snapshot));
const progress = [];
bridge.on(Event.PROGRESS, (e) => progress.push(e.progress));
const wasmBase = new URL('./fixtures/fake_wasm/', import.meta.url).href;
const replies = () => posted.filter((p) => p.msg.type === 'reply');

test('a request before init is refused with a clear message', async () => {
  await assert.rejects(bridge.estimate(8), { message: 'the core is not ready yet' });
});

test('an unknown request type is refused by name', async () => {
  await assert.rejects(bridge.request('explode', { x: 1 }), { message: "unknown request 'explode'" });
});

test('a failed init rejects and also raises the fatal event with the same message', async () => {
  const error = await bridge.request('init', { wasmBase: wasmBase + 'missing/', threaded: false }).then(
    () => assert.fail('init should fail'), (e) => e.message);
  assert.match(error, /zomeify_web_st\.mjs/); // names the module it could not load
  assert.deepEqual(fatal, [error]);
});

test('init loads the single-threaded module when not threaded', async () => {
  assert.deepEqual(await bridge.request('init', { wasmBase, threaded: false }),
    { threaded: false, maxThreads: 1, ...SCHEMA });
});

test('every request gets exactly one reply, with its own id', () => {
  const ids = replies().map((p) => p.msg.id);
  assert.deepEqual(ids, [1, 2, 3, 4]);
});

test('load: a mesh replies with its report, and its bytes are transferred, not copied', async () => {
  const bytes = new Uint8Array([1, 2, 3, 4, 5]).buffer;
  const result = await bridge.load('tetra.obj', bytes);
  assert.deepEqual(result, { kind: 'mesh', report: { vertices: 4, faces: 4, genus: 0, bytes: 5 } });
  assert.deepEqual(sent.at(-1), [bytes]);
});

test('load: a model sends its snapshot event before the reply (the page fits on it)', async () => {
  const order = [];
  const before = snapshots.length;
  bridge.on(Event.SNAPSHOT, () => order.push('snapshot'));
  await bridge.load('torus.zome.json', new ArrayBuffer(3)).then(() => order.push('reply'));
  assert.deepEqual(order, ['snapshot', 'reply']);
  assert.equal(snapshots.length, before + 1);
  assert.deepEqual(Array.from(snapshots.at(-1).struts), [0, 1]);
});

test("the core's error reaches the page verbatim as an Error", async () => {
  await assert.rejects(bridge.load('empty.obj', new ArrayBuffer(0)), { message: 'empty.obj: the file is empty' });
  await assert.rejects(bridge.openLink('https://x/#q=2'), { message: 'not a share link (no m=1.…)' });
});

test('a C++ exception thrown as a number becomes "internal error (n)"', async () => {
  await assert.rejects(bridge.load('crash.obj', new ArrayBuffer(1)), { message: 'internal error (5251072)' });
});

test('export: bytes come back (transferred); an unknown format is a clear error', async () => {
  const out = await bridge.exportModel('torus.vef');
  assert.equal(out.name, 'torus.vef');
  assert.deepEqual(Array.from(out.bytes), [1, 2, 3]);
  assert.deepEqual(posted.at(-1).transfer, [out.bytes.buffer]);
  await assert.rejects(bridge.exportModel('torus.xyz'), { message: "unknown export format '.xyz'" });
});

test('export with options: VEF without faces, OBJ in metres reach the core', async () => {
  const plain = await bridge.exportModel('torus.vef', { vefFaces: false });
  assert.deepEqual(Array.from(plain.bytes), [1, 2, 3, 0, 0]);
  const metres = await bridge.exportModel('torus.obj', { objUnits: 'm' });
  assert.deepEqual(Array.from(metres.bytes), [1, 2, 3, 1, 1]);
});

test('snapshot: the reply hands over all four typed-array buffers', async () => {
  const s = await bridge.snapshot();
  assert.equal(posted.at(-1).transfer.length, 4);
  assert.ok(posted.at(-1).transfer.includes(s.positions.buffer));
  assert.ok(posted.at(-1).transfer.includes(s.kinds.buffer));
});

test('single-threaded run: options reach the core unchanged; progress and a changed model are sent', async () => {
  const options = { resolution: 8, seconds: 5, proposals: 0, threads: 1, seed: 7, weights: { dist: 10 } };
  const before = snapshots.length;
  const final = await bridge.run(options);
  assert.deepEqual(globalThis.fakeSession.options, options);
  assert.equal(final.state, 'done');
  assert.deepEqual(progress.map((p) => p.state), ['annealing', 'annealing']);
  assert.equal(snapshots.length, before + 1); // one new model version, sent once
  // The run's first model goes to the page at once as a checkpoint (not a second later), so a
  // Cancel right after it keeps this run's model; the finished model was that same version.
  const checkpoints = posted.filter((p) => p.msg.type === Event.CHECKPOINT);
  assert.equal(checkpoints.length, 1);
  assert.equal(bridge.kept.model.name, 'checkpoint.zome.json');
});

test('threaded run: a second run is refused, cancel stops the first with state "cancelled"', async () => {
  assert.deepEqual(await bridge.request('init', { wasmBase, threaded: true }),
    { threaded: true, maxThreads: 4, ...SCHEMA });
  const first = bridge.run({ seconds: 30 });
  await assert.rejects(bridge.run({ seconds: 30 }), { message: 'a run is in progress' });
  await new Promise((resolve) => setTimeout(resolve, 250)); // a couple of 100 ms progress polls
  assert.ok(progress.at(-1).state === 'annealing');
  assert.deepEqual(await bridge.cancel(), {});
  const final = await first;
  assert.equal(final.state, 'cancelled');
  assert.ok(final.seconds < 5, `stopped early (${final.seconds} s)`);
});
