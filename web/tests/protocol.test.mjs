// The typed protocol (protocol.js) and the page's side of it (bridge.js) against a scripted
// worker: ids, transfers, replies matched out of order, errors, events; and the README's tables
// saying the same as the code.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { Request, Event, KIND_NAMES } from '../src/protocol.js';
import { CoreBridge } from '../src/bridge.js';

const readme = readFileSync(new URL('../README.md', import.meta.url), 'utf8');

/** The first column (`name`) of the markdown table whose header starts with `| heading |`. */
function tableNames(heading) {
  const lines = readme.split('\n');
  const start = lines.findIndex((l) => l.startsWith(`| ${heading} |`));
  const names = [];
  for (let i = start + 2; i < lines.length && lines[i].startsWith('|'); i++) names.push(lines[i].match(/^\| `([^`]+)`/)[1]);
  return names;
}

function scriptedBridge() {
  const bridge = new CoreBridge();
  const sent = [];
  bridge.worker = { postMessage: (msg, transfer = []) => sent.push({ msg, transfer }) };
  return { bridge, sent };
}

test('web/README.md documents exactly the requests and events protocol.js defines', () => {
  assert.deepEqual(tableNames('request').sort(), Object.values(Request).sort());
  assert.deepEqual(tableNames('event').sort(), Object.values(Event).sort());
});

test('KIND_NAMES: the nine Zome strut kinds in the core\'s order B0..R2', () => {
  assert.deepEqual(KIND_NAMES, ['B0', 'B1', 'B2', 'Y0', 'Y1', 'Y2', 'R0', 'R1', 'R2']);
});

test('a request is {id, type, ...fields}, with ids counting up and buffers in the transfer list', () => {
  const { bridge, sent } = scriptedBridge();
  const bytes = new ArrayBuffer(8);
  bridge.load('a.obj', bytes);
  bridge.estimate(12, 300);
  bridge.run({ seconds: 5 });
  assert.deepEqual(sent.map((s) => s.msg), [
    { id: 1, type: 'load', name: 'a.obj', bytes, thicken: false },
    { id: 2, type: 'estimate', resolution: 12, target: 300, kits: true },
    { id: 3, type: 'run', options: { seconds: 5 } },
  ]);
  assert.deepEqual(sent[0].transfer, [bytes]);
  assert.deepEqual(sent[1].transfer, []);
});

test('replies settle their own request even out of order; ok:false rejects with the message', async () => {
  const { bridge } = scriptedBridge();
  const estimate = bridge.estimate(8);
  const parts = bridge.parts();
  bridge.receive({ id: 2, type: 'reply', ok: false, error: 'no model yet' });
  bridge.receive({ id: 1, type: 'reply', ok: true, result: { nodes: 80 } });
  assert.deepEqual(await estimate, { nodes: 80 });
  await assert.rejects(parts, (e) => e instanceof Error && e.message === 'no model yet');
  assert.equal(bridge.pending.size, 0);
});

test('a reply nobody waits for (unknown or repeated id) is ignored', async () => {
  const { bridge } = scriptedBridge();
  const link = bridge.link();
  bridge.receive({ id: 1, type: 'reply', ok: true, result: { link: 'm=1.A' } });
  bridge.receive({ id: 1, type: 'reply', ok: false, error: 'late duplicate' });
  bridge.receive({ id: 99, type: 'reply', ok: true, result: {} });
  assert.deepEqual(await link, { link: 'm=1.A' });
});

test('events go to every listener of their type, with the whole message', () => {
  const { bridge } = scriptedBridge();
  const got = [];
  bridge.on(Event.PROGRESS, (m) => got.push(['a', m.progress.state]));
  bridge.on(Event.PROGRESS, (m) => got.push(['b', m.progress.state]));
  bridge.on(Event.FATAL, (m) => got.push(['fatal', m.error]));
  bridge.receive({ type: 'progress', progress: { state: 'annealing' } });
  bridge.receive({ type: 'fatal', error: 'no wasm' });
  assert.deepEqual(got, [['a', 'annealing'], ['b', 'annealing'], ['fatal', 'no wasm']]);
});

test('an unknown event is dropped (not thrown in onmessage); listening to one is a clear error', () => {
  const { bridge } = scriptedBridge();
  assert.doesNotThrow(() => bridge.receive({ type: 'gossip', text: 'hi' }));
  assert.throws(() => bridge.on('progres', () => {}), { message: "unknown event 'progres'" });
});
