// model_json.js: the page's own .zome.json reader (the first sample is drawn from it before the
// core is up). Real Zome proportions, node coordinates in Q(φ), kinds recognised from lengths
// on a real sample (fixtures/torus.zome.json, made by the native CLI), and one clear Error
// for bad input.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { snapshotFromZomeJson, ZOME_LENGTHS, kindOfLength } from '../src/model_json.js';
import { KIND_NAMES } from '../src/protocol.js';

const PHI = (1 + Math.sqrt(5)) / 2;
const MM_PER_B0 = 8.8365 * 2 * (PHI + 1); // core/zome/real_sizes.h: kMmPerB0 (46.27 mm)
const fixture = (name) => readFileSync(new URL(`./fixtures/${name}`, import.meta.url), 'utf8');
const model = (fields) => JSON.stringify({ format: 'zomeify-model', version: 1, nodes: [], struts: [], ...fields });
const close = (a, b, eps = 1e-6) => Math.abs(a - b) <= eps;

test('Zome proportions: yellow = √3/2 and red = √(2+φ)/2 of blue; each size φ times the last', () => {
  const [b0, b1, b2, y0, y1, y2, r0, r1, r2] = ZOME_LENGTHS;
  assert.equal(b0, 1);
  assert.ok(close(y0, 0.8660254) && close(r0, 0.9510565));
  for (const [s0, s1, s2] of [[b0, b1, b2], [y0, y1, y2], [r0, r1, r2]]) assert.ok(close(s1 / s0, PHI) && close(s2 / s1, PHI));
});

test('in millimetres the lengths match the real parts the core lists (parts report)', () => {
  const report = JSON.parse(fixture('cube.parts.json'));
  for (const k of report.kinds) {
    const mm = ZOME_LENGTHS[KIND_NAMES.indexOf(k.kind)] * MM_PER_B0;
    assert.ok(Math.abs(mm - k.length_mm) < 0.006, `${k.kind}: ${mm.toFixed(3)} mm vs the core's ${k.length_mm}`);
  }
});

test('kindOfLength: 1 % tolerance is unambiguous (lengths differ by ≥ 5 %), else 255', () => {
  const sorted = [...ZOME_LENGTHS].sort((a, b) => a - b);
  for (let i = 1; i < sorted.length; i++) assert.ok(sorted[i] / sorted[i - 1] > 1.05);
  assert.equal(kindOfLength(1.009), 0);
  assert.equal(kindOfLength(0.9510565 * PHI * 0.995), 7); // R1
  assert.equal(kindOfLength(1.02), 255);
  assert.equal(kindOfLength(0), 255);
});

test('nodes are (a·φ + b)/2 per axis; B0, Y0 and R0 struts are recognised', () => {
  const s = snapshotFromZomeJson(model({
    nodes: [[0, 0, 0, 0, 0, 0], [0, 2, 0, 0, 0, 0], [0, 1, 0, 1, 0, 1], [0, 0, 0, 1, 1, 0], [2, 0, 0, 0, 0, 0]],
    struts: [[0, 1], [0, 2], [0, 3], [0, 4], [1, 4]],
  }));
  assert.ok(close(s.positions[9 + 1], 0.5) && close(s.positions[9 + 2], PHI / 2, 1e-6)); // node 3 = (0, ½, φ/2)
  assert.deepEqual(Array.from(s.kinds), [0, 3, 6, 1, 255]); // B0 Y0 R0 B1, and 1→4 (length φ−1) is no strut
  assert.deepEqual(Array.from(s.struts), [0, 1, 0, 2, 0, 3, 0, 4, 1, 4]);
});

test('faces become a triangle fan; no transform means scale 1 at the origin', () => {
  const s = snapshotFromZomeJson(model({ nodes: Array(5).fill([0, 0, 0, 0, 0, 0]), faces: [[0, 1, 2, 3, 4], [4, 3, 2]] }));
  assert.deepEqual(Array.from(s.triangles), [0, 1, 2, 0, 2, 3, 0, 3, 4, 4, 3, 2]);
  assert.equal(s.scale, 1);
  assert.deepEqual(s.translation, [0, 0, 0]);
  assert.equal(s.version, -1); // below any core version, so the core's first snapshot replaces it
});

test('a real sample: every strut gets the kind the core counted, and the transform is kept', () => {
  const text = fixture('torus.zome.json');
  const { stats, transform, faces } = JSON.parse(text);
  const s = snapshotFromZomeJson(text);
  const counts = Object.fromEntries(KIND_NAMES.map((k) => [k, 0]));
  for (const k of s.kinds) counts[KIND_NAMES[k]]++; // a 255 would count as "undefined"
  assert.deepEqual(counts, stats.struts_by_kind);
  assert.equal(s.positions.length, 3 * stats.N);
  assert.equal(s.triangles.length, 3 * faces.reduce((n, f) => n + f.length - 2, 0));
  assert.equal(s.scale, transform.scale);
  assert.deepEqual(s.translation, transform.translation);
});

test('bad input throws one clear Error, never a TypeError from deep inside', () => {
  const cases = [
    ['{"nodes": [', /^not a zomeify model \(.*JSON.*\)$/],
    ['null', /^not a zomeify model$/],
    ['{"format": "vzome", "nodes": [], "struts": []}', /^not a zomeify model$/],
    [model({ struts: 'none' }), /^not a zomeify model$/],
    [model({ nodes: [[0, 0, 0, 0, 0, 0], [1, 2, 3]] }), /^node 1 is not 6 numbers$/],
    [model({ nodes: [[0, 0, 0, 0, 0, 'x']] }), /^node 0 is not 6 numbers$/],
    [model({ nodes: [[0, 0, 0, 0, 0, 0]], struts: [[0, 0], [0, 1]] }), /^strut 1 refers to a missing node$/],
    [model({ nodes: [[0, 0, 0, 0, 0, 0]], struts: [[0, -1]] }), /^strut 0 refers to a missing node$/],
    [model({ nodes: [[0, 0, 0, 0, 0, 0]], faces: [[0, 0, 7]] }), /^face 0 refers to a missing node$/],
  ];
  for (const [text, message] of cases) {
    assert.throws(() => snapshotFromZomeJson(text), (e) => e.constructor === Error && message.test(e.message), text);
  }
});
