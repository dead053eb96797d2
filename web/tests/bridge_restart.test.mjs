// bridge.js, single-threaded build: Cancel ends the blocked worker, resolves the run as cancelled
// at once, and a fresh worker gets the mesh and the last checkpoint before any later request.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { CoreBridge } from '../src/bridge.js';
import { Request, Event } from '../src/protocol.js';
import { setGlobal } from './helpers/fake_dom.mjs';

/** A worker that records what it is sent and answers INIT/LOAD/SUMMARY at once, but never RUN. */
class FakeWorker {
  static made = [];
  constructor() {
    this.sent = [];
    this.terminated = false;
    FakeWorker.made.push(this);
  }
  postMessage(msg) {
    this.sent.push(msg);
    const reply = (result) => queueMicrotask(() => this.onmessage({ data: { id: msg.id, type: 'reply', ok: true, result } }));
    if (msg.type === Request.INIT) reply({ threaded: false, maxThreads: 1 });
    if (msg.type === Request.LOAD) reply({ kind: msg.name.endsWith('.obj') ? 'mesh' : 'model' });
    if (msg.type === Request.SUMMARY) reply({ balls: 7 });
  }
  terminate() { this.terminated = true; }
}

test('single-threaded cancel: the run resolves cancelled at once; a fresh worker reloads mesh and checkpoint', async () => {
  const restore = [setGlobal('Worker', FakeWorker), setGlobal('document', { baseURI: 'http://x/' }),
    setGlobal('self', { crossOriginIsolated: false })];
  try {
    const bridge = new CoreBridge();
    await bridge.start();
    await bridge.load('shape.obj', new Uint8Array([1, 2, 3]).buffer);
    const run = bridge.run({ seconds: 60 });
    const first = FakeWorker.made.at(-1);
    first.onmessage({ data: { type: Event.PROGRESS, progress: { state: 'annealing', seconds: 3, fraction: 0.05, nodes: 90 } } });
    first.onmessage({ data: { type: Event.CHECKPOINT, name: 'checkpoint.zome.json', bytes: new Uint8Array([9]).buffer } });
    const final = await bridge.cancel();
    assert.equal(first.terminated, true);
    assert.equal(final.state, 'cancelled');
    assert.equal(final.fraction, 0.05);
    assert.deepEqual(await run, final);
    const summary = await bridge.summary(); // waits for the fresh worker
    assert.deepEqual(summary, { balls: 7 });
    const fresh = FakeWorker.made.at(-1);
    assert.notEqual(fresh, first);
    assert.deepEqual(fresh.sent.map((m) => [m.type, m.name]),
      [[Request.INIT, undefined], [Request.LOAD, 'shape.obj'], [Request.LOAD, 'checkpoint.zome.json'], [Request.SUMMARY, undefined]]);
    assert.deepEqual([...new Uint8Array(fresh.sent[1].bytes)], [1, 2, 3]);
  } finally {
    restore.forEach((r) => r());
  }
});

test('single-threaded cancel before the run\'s first model: the model from before is kept, and the bar says so', async () => {
  const restore = [setGlobal('Worker', FakeWorker), setGlobal('document', { baseURI: 'http://x/' }),
    setGlobal('self', { crossOriginIsolated: false })];
  try {
    const bridge = new CoreBridge();
    const events = [];
    bridge.on(Event.PROGRESS, ({ progress }) => events.push(progress));
    await bridge.start();
    await bridge.load('before.zome.json', new Uint8Array([5]).buffer);
    await bridge.load('shape.obj', new Uint8Array([1]).buffer);
    const run = bridge.run({ seconds: 60 });
    const first = FakeWorker.made.at(-1);
    first.onmessage({ data: { type: Event.PROGRESS, progress: { state: 'initial', seconds: 0.4, fraction: 0, nodes: 0 } } });
    const final = await bridge.cancel();
    assert.equal(final.state, 'cancelled');
    assert.equal(final.nodes, 0); // no model of this run: the page keeps treating the old one as old
    assert.match(final.note, /before it made a model/);
    assert.deepEqual(events.at(-1), final); // the bar and the progress line hear the end too
    assert.deepEqual(await run, final);
    await bridge.summary();
    const fresh = FakeWorker.made.at(-1);
    assert.deepEqual(fresh.sent.map((m) => m.name).filter(Boolean), ['shape.obj', 'before.zome.json']);
  } finally {
    restore.forEach((r) => r());
  }
});
