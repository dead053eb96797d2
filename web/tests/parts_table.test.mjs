// parts_table.js: rows, totals and kit plan from a real parts report (fixtures/cube.parts.json,
// `zomeify parts --json` of the cube sample), the swatch colours, and hover → highlight.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { partRows, totalsText, kitPlanText, SWATCH, PartsTable, halvesText } from '../src/parts_table.js';
import { COLOURS, KIND_COLOUR, BALL_RADIUS } from '../src/render/scene.js';
import { fakeRoot, fakeDocument, setGlobal } from './helpers/fake_dom.mjs';

const report = () => JSON.parse(readFileSync(new URL('./fixtures/cube.parts.json', import.meta.url), 'utf8'));

test('rows: the ball first, then the strut kinds in the core\'s order B0..R2, lengths to 0.01 mm', () => {
  const rows = partRows(report());
  assert.deepEqual(rows.map((r) => r.kind), ['ball', 'B0', 'B1', 'B2', 'Y0', 'Y1', 'Y2', 'R0', 'R1', 'R2']);
  assert.deepEqual(rows[0], { part: 'PZB-BAL-W', kind: 'ball', length: '17.67', count: 226, color: 'white', kindIds: null });
  assert.deepEqual(rows[6], { part: 'PST-Y2-YEL', kind: 'Y2', length: '104.90', count: 15, color: 'yellow', kindIds: [5] });
  assert.equal(rows[7].length, '44.00'); // R0: trailing zeros kept, as in the CLI's table
});

test('kinds with no struts get no row (and the others keep their kind ids)', () => {
  const r = report();
  for (const k of r.kinds) if (k.kind === 'B2' || k.kind === 'R2') k.count = 0;
  const rows = partRows(r);
  assert.deepEqual(rows.map((x) => x.kind), ['ball', 'B0', 'B1', 'Y0', 'Y1', 'Y2', 'R0', 'R1']);
  assert.deepEqual(rows.find((x) => x.kind === 'R1').kindIds, [7]);
});

test('totals line: the CLI\'s numbers (38.11 m; 49.0 × 46.7 × 45.3 cm)', () => {
  assert.equal(totalsText(report()), '226 balls, 577 struts, 38.11 m of struts; built size 49.0 × 46.7 × 45.3 cm');
});

test('kit plan line, and "none" when the model needs no kit', () => {
  assert.equal(kitPlanText(report().kit_plan), 'Kit plan: 2 × Creator 3 + 1 × Creator 1 + 1 × Basic (1845 parts bought)');
  assert.equal(kitPlanText({ kits: [], parts_bought: 0 }), 'Kit plan: none (0 parts bought)');
});

test('swatches are the viewer\'s strut colours, and each kind\'s colour is the one it is drawn in', () => {
  for (const c of ['blue', 'yellow', 'red']) assert.equal(SWATCH[c], '#' + COLOURS[c].toString(16).padStart(6, '0'));
  for (const row of partRows(report()).slice(1)) assert.equal(KIND_COLOUR[row.kindIds[0]], row.color, row.kind);
  assert.equal((2 * BALL_RADIUS * 46.27).toFixed(2), partRows(report())[0].length); // the ball drawn as listed
});

test('the table on the page: hovering a strut row highlights its kind; leaving clears it', () => {
  const restore = setGlobal('document', fakeDocument());
  try {
    const hovered = [];
    const root = fakeRoot();
    const table = new PartsTable(root, { onHover: (ids) => hovered.push(ids) });
    table.show(report());
    const rows = root.querySelector('#parts-table').children;
    assert.equal(rows.length, 11); // header, ball, nine kinds
    assert.deepEqual(rows[0].children.map((c) => c.text), ['part', 'kind', 'length mm', 'count']);
    const r1 = rows.find((r) => r.dataset.kind === 'R1');
    assert.deepEqual(r1.children.map((c) => c.text), ['PST-R1-RED', 'R1', '71.20', '54']);
    assert.equal(r1.children[1].children[0].style.background, SWATCH.red);
    r1.dispatch('mouseenter');
    r1.dispatch('mouseleave');
    rows[1].dispatch('mouseenter'); // the ball row highlights nothing
    assert.deepEqual(hovered, [[7], null]);
    assert.equal(r1.tabIndex, 0); // reachable with Tab, and focus highlights as hover does
    r1.dispatch('focus');
    r1.dispatch('blur');
    assert.deepEqual(hovered, [[7], null, [7], null]);
    assert.match(root.querySelector('#parts-totals').textContent, /^226 balls, 577 struts/);
    table.clear();
    assert.equal(root.querySelector('#parts-table').children.length, 0);
    assert.equal(root.querySelector('#kit-plan').textContent, '');
  } finally {
    restore();
  }
});

test('a mirror-symmetric model\'s parts by half; nothing for another model', () => {
  const mirror = { axis: 'x', half: { balls: 173, strut_count: 443 }, middle: { balls: 24, strut_count: 36 } };
  assert.equal(halvesText(mirror), 'Mirror-symmetric: build one half (173 balls, 443 struts) twice, the second ' +
    'mirrored, then the middle (24 balls, 36 struts) on the plane or across it.');
  assert.equal(halvesText(undefined), '');
});
