// build_view.js: the step index maps, the step text and the running counts, from a small plan in
// the core's plan_json shape (a square of four balls with a diagonal, then an apex).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { stepIndexMaps, stepRows, countsThrough, stepText, figuresText } from '../src/build_view.js';

const plan = {
  nodes: [[0, 0, 0, 0, 0, 0], [0, 2, 0, 0, 0, 0], [0, 2, 0, 0, 0, 2], [0, 0, 0, 0, 0, 2], [0, 1, 0, 2, 0, 1]],
  steps: [
    { balls: [0, 1, 2, 3], struts: [[1, 0], [2, 1], [2, 0], [3, 2], [3, 0]], attach: [], parts: { 'PZB-BAL-W': 4, 'PST-B0-BLU': 5 } },
    { balls: [4], struts: [[4, 0], [4, 2]], attach: [0, 2], parts: { 'PZB-BAL-W': 1, 'PST-Y0-YEL': 2 } },
  ],
  figures: { steps: 2, max_overhang_b0: 1, max_overhang_mm: 46.27, two_strut_share: 1 },
};

test('index maps: each snapshot strut (either direction) and each ball gets the step that adds it', () => {
  const snapshotStruts = new Uint32Array([0, 1, 1, 2, 2, 3, 3, 0, 0, 2, 0, 4, 2, 4]);
  const { strutStep, ballStep } = stepIndexMaps(plan, snapshotStruts, 5);
  assert.deepEqual([...strutStep], [0, 0, 0, 0, 0, 1, 1]);
  assert.deepEqual([...ballStep], [0, 0, 0, 0, 1]);
});

test('a strut the plan does not know stays at -1 (drawn faint, never as built)', () => {
  const { strutStep } = stepIndexMaps(plan, new Uint32Array([1, 3]), 5);
  assert.deepEqual([...strutStep], [-1]);
});

test('step text, rows and counts', () => {
  assert.equal(stepText(plan, 0), 'Step 1 of 2: 4 balls, 5 struts, on the table.');
  assert.equal(stepText(plan, 1), 'Step 2 of 2: 1 ball, 2 struts, attached to 2 balls built before.');
  assert.deepEqual(stepRows(plan.steps[1]), [{ code: 'PZB-BAL-W', count: 1 }, { code: 'PST-Y0-YEL', count: 2 }]);
  assert.deepEqual(countsThrough(plan, 0), { balls: 4, struts: 5 });
  assert.deepEqual(countsThrough(plan, 1), { balls: 5, struts: 7 });
  assert.equal(figuresText(plan), '2 steps; largest overhang 46 mm; 100% of steps end with every new ball on two struts.');
  assert.equal(figuresText({ ...plan, mirror: { axis: 'z', coordinate_b0: 0 } }), '2 steps; largest overhang 46 mm; ' +
    '100% of steps end with every new ball on two struts. Both halves are built alike: each step adds its parts ' +
    'with their mirror images about the plane across the z axis.');
});
