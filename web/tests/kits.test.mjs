// kits.js and the controls' size field and kits picker: the --have text from the picker, the size's
// range, the sentences before and after a run, and "Fit my kits" setting the form (on a fake DOM;
// the core's answers are fixed fixtures in the shape Session::kit_check / fit_kits / estimate_size return;
// e2e/kits.spec.js runs the same page against the real core).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { haveText, ownedName, checkSize, estimateFitText, resultFitText, missingText, fitPlanText, SIZE_CM } from '../src/kits.js';
import { Controls } from '../src/controls.js';
import { fakeRoot, fakeDocument, setGlobal } from './helpers/fake_dom.mjs';

setGlobal('navigator', { hardwareConcurrency: 3 });
setGlobal('document', fakeDocument());

test('haveText: the picker as the core\'s --have syntax; a bad count names the kit', () => {
  assert.deepEqual(haveText({ basic: '2', creator1: '0', creator3: '1', workshop: '' }),
    { have: '2x basic, 1x creator3', error: '' });
  assert.deepEqual(haveText({}), { have: '', error: '' });
  assert.equal(ownedName('2x basic, 1x creator3'), '2 x Basic + 1 x Creator 3');
  assert.match(haveText({ creator3: '-1' }).error, /^Creator 3: the number of kits must be a whole number from 0 to 99/);
  assert.match(haveText({ basic: '1.5' }).error, /^Basic:/);
  assert.match(haveText({ workshop: '1e9' }).error, /^Workshop:/);
});

test('checkSize: centimetres within the core\'s range, a sentence otherwise', () => {
  assert.deepEqual(checkSize('50'), { cm: 50, error: '' });
  for (const bad of ['-50', '0', '5', '100000', 'abc', '']) {
    assert.equal(checkSize(bad).cm, 0, bad);
    assert.equal(checkSize(bad).error, `The size must be a number of centimetres from ${SIZE_CM.min} to ${SIZE_CM.max}.`);
  }
});

test('sentences: before the run (estimate), after it (the result), and the fit plan', () => {
  assert.equal(estimateFitText({ fits: true, owned: '1 x Creator 3', text: 'fits your kits' }, 90),
    'With your kits (1 x Creator 3): a model of about 90 balls typically fits; the result is checked after the run.');
  assert.match(estimateFitText({ fits: false, owned: '1 x Basic', text: 'missing with your kits: 9 R1' }, 90),
    /typically does not fit \(missing with your kits: 9 R1\)\. Try "Fit my kits"\./);
  assert.equal(missingText({ B0: 0, R1: 4, balls: 2 }), '4 R1, 2 balls');
  assert.equal(resultFitText({ missing: { B0: 0, R1: 0, balls: 0 } }, '1x creator3'),
    'Your kits (1x creator3) hold every part of this model.');
  assert.match(resultFitText({ missing: { R1: 3, balls: 0 } }, '1x creator3'), /do not hold this model: missing 3 R1\./);
  assert.equal(resultFitText({}, 'x'), '');
  const plan = { possible: true, owned: '1 x Creator 3', resolution: 6, size_cm: 41.2, target_nodes: 96, genus_kept: true };
  assert.equal(fitPlanText(plan), 'Fit my kits (1 x Creator 3): 6 cells, target 96 balls, kept below what the kits ' +
    'hold as the strut mix varies. Press Run: the result is checked against your kits.');
  // Issue 38: no size of its own (the estimate line has the one size), and a plan stopped by the size
  // asked says that the size, not the kits, decided it.
  assert.match(fitPlanText(plan, { cm: 34, resolution: 6 }),
    /Your size limit \(at most 34 cm\) decided this, not the kits: they hold a larger model\./);
  assert.doesNotMatch(fitPlanText(plan, { cm: 34, resolution: 9 }), /size limit/);
  assert.equal(fitPlanText(plan).match(/checked/g).length, 1);
  assert.equal(fitPlanText({ possible: false, owned: '1 x Basic', message: 'no size of this shape fits: …' }),
    'Cannot fit your kits (1 x Basic): no size of this shape fits: ….');
});

function makeControls() {
  const root = fakeRoot();
  const calls = { estimate: [], size: [], check: [], fit: [] };
  const controls = new Controls(root, {
    estimate: async (r) => { calls.estimate.push(r); return { nodes: 10 * r, struts: 20 * r, kept: true }; },
    estimateSize: async (cm) => { calls.size.push(cm); return { nodes: 300, struts: 600, kept: true, resolution: 9, size_cm: cm }; },
    kitCheck: async (have, balls) => { calls.check.push([have, balls]); return { fits: balls <= 100, owned: have, text: 'missing with your kits: 5 R1' }; },
    fitKits: async (have, maxResolution, shrink) => {
      calls.fit.push([have, maxResolution, shrink]);
      return { possible: true, owned: have, resolution: 6, target_nodes: 96, size_cm: 41, genus_kept: true, message: '' };
    },
  });
  clearTimeout(controls.estimateTimer);
  controls.maxThreads = 4;
  return { controls, el: (id) => root.querySelector('#' + id), calls };
}

test('size field: the estimate asks the core for that size, get() carries size_cm, a bad size is said', async () => {
  const { controls, el, calls } = makeControls();
  controls.set({ size_cm: 50 });
  clearTimeout(controls.estimateTimer);
  assert.equal(el('size-mode').checked, true);
  assert.equal(el('resolution').disabled, true);
  await controls.updateEstimate();
  assert.deepEqual(calls.size, [50]);
  assert.match(el('estimate').textContent, /^At 50 cm \(about 9 cells\): The model: ≈ 300 balls/);
  assert.equal(controls.get().size_cm, 50);
  el('size-cm').value = '-3';
  await controls.updateEstimate();
  assert.match(el('estimate').textContent, /^The size must be a number of centimetres/);
  assert.match(controls.runBlocker(), /The size must be/);
  controls.set({ resolution: 8 }); // choosing a resolution leaves the size
  clearTimeout(controls.estimateTimer);
  assert.equal(el('size-mode').checked, false);
  assert.equal(controls.get().size_cm, 0);
});

test('kits picker: the line before the run says whether the estimate fits; Fit my kits sets the form', async () => {
  const { controls, el, calls } = makeControls();
  el('kit-creator3').value = '1';
  controls.set({ resolution: 12 });
  clearTimeout(controls.estimateTimer);
  await controls.updateEstimate();
  await new Promise((r) => setTimeout(r, 0));
  assert.deepEqual(calls.check.at(-1), ['1x creator3', 120]);
  assert.match(el('kit-fit').textContent, /typically does not fit \(missing with your kits: 5 R1\)/);
  const plan = await controls.fitMyKits();
  clearTimeout(controls.estimateTimer);
  assert.equal(plan.resolution, 6);
  assert.deepEqual(calls.fit.at(-1), ['1x creator3', 0, false]);
  assert.equal(el('resolution').value, '6');
  assert.equal(el('target').value, '96');
  assert.match(el('kit-fit').textContent, /^Fit my kits \(1x creator3\): 6 cells/);
  await controls.updateEstimate();
  await new Promise((r) => setTimeout(r, 0));
  // The plan's sentence alone, not the plan and the typical-fit line saying the same thing twice.
  assert.match(el('kit-fit').textContent, /^Fit my kits \(1x creator3\): 6 cells.*checked against your kits\.$/);
  assert.doesNotMatch(el('kit-fit').textContent, /typically fits/);
  controls.kitsMissed = true; // the run missed: the next plan shrinks from the result
  await controls.fitMyKits();
  clearTimeout(controls.estimateTimer);
  assert.equal(calls.fit.at(-1)[2], true);
});

test('kits picker: no kits or a bad count gives a sentence, not a call', async () => {
  const { controls, el, calls } = makeControls();
  assert.equal(await controls.fitMyKits(), null);
  assert.match(el('kit-fit').textContent, /^Choose the kits you own first/);
  el('kit-basic').value = '-2';
  assert.equal(await controls.fitMyKits(), null);
  assert.match(el('kit-fit').textContent, /^Basic: the number of kits must be/);
  assert.equal(calls.fit.length, 0);
});
