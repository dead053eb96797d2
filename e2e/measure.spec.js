// Measurements on the ten shared meshes, in the page with nothing touched (issue 38); about 8
// minutes, so only with E2E_MEASURE=1 (`E2E_MEASURE=1 bash e2e/run.sh measure.spec.js`):
// - the kits named before a run (a short pass from Z0, which the run then keeps within) hold every
//   part of the model a default run makes, and exceed its kit plan by at most one Creator 3 on at
//   least 8 of 10;
// - the quick preset ends within its time plus the set-up time the line under it promises.
// Each prints its table (build/e2e-results/measure-*.md too).
import fs from 'node:fs';
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { MESHES, OUT, SHARED_MISSING } from './support/paths.js';
import { openPage, pickFile, waitIdle } from './support/page.js';

test.skip(!process.env.E2E_MEASURE, 'a measurement: E2E_MEASURE=1 runs it');
test.skip(Boolean(SHARED_MISSING), SHARED_MISSING);
test.setTimeout(20 * 60_000);

const meshes = fs.existsSync(MESHES) ? fs.readdirSync(MESHES).filter((f) => f.endsWith('.obj')).sort() : [];
const CREATOR3_PARTS = 3 * (90 + 60 + 36) + 180; // core/parts/kits.cpp

/** "2 Creator 3 + 1 Basic" (the core's plan text) as the kits picker's `--have` text. */
const haveOf = (plan) => plan.split(' + ').map((item) => {
  const [, n, name] = item.match(/^(\d+) (.+)$/);
  return `${n}x ${name.replace(/\s+/g, '').toLowerCase()}`;
}).join(', ');

/** Loads a mesh as a user does ("run after loading" off) and waits for the page's estimate. */
async function load(page, file) {
  await pickFile(page, file, fs.readFileSync(path.join(MESHES, file)));
  await page.waitForFunction((name) => document.getElementById('surface-info').textContent.startsWith(name)
    && window.zomeify.estimate()?.kit_plan, file, { timeout: 60_000, polling: 100 });
  return page.evaluate(() => window.zomeify.estimate());
}

test('kits named before a default run hold the plan after it', async ({ page }) => {
  await openPage(page);
  await page.locator('#autorun').uncheck();
  const rows = ['| mesh | cells | Z0 balls | before: range | after: plan | balls | holds every part | extra parts |',
    '|---|---|---|---|---|---|---|---|'];
  let holds = 0, tight = 0;
  for (const file of meshes) {
    const e = await load(page, file);
    const runs = await page.evaluate(() => window.zomeify.runs());
    await page.locator('#run').click(); // the default time, nothing touched
    await page.waitForFunction((n) => window.zomeify.runs() > n, runs, { timeout: 180_000 });
    await waitIdle(page);
    const report = await page.evaluate((have) => window.zomeify.parts(have), haveOf(e.kit_plan));
    const missing = Object.values(report.missing).reduce((a, b) => a + b, 0);
    const plan = report.kit_plan.kits.map((k) => `${k.count} ${k.name}`).join(' + ');
    const extra = e.kit_plan_parts - report.kit_plan.parts_bought;
    holds += missing === 0;
    tight += missing === 0 && extra <= CREATOR3_PARTS;
    rows.push(`| ${file} | ${e.resolution} | ${e.nodes} | ${e.kit_plan_low} … ${e.kit_plan} | ${plan} | ` +
      `${report.balls} | ${missing === 0 ? 'yes' : `no (${missing} parts short)`} | ${extra} |`);
  }
  rows.push(`holds the plan on ${holds} of ${meshes.length}; within one Creator 3 (${CREATOR3_PARTS} parts) on ${tight}`);
  console.log(rows.join('\n'));
  fs.writeFileSync(path.join(OUT, 'measure-kits.md'), rows.join('\n') + '\n');
  expect(holds).toBe(meshes.length);
  expect(tight).toBeGreaterThanOrEqual(Math.ceil(0.8 * meshes.length));
});

test('the quick preset ends within its time plus the set-up time it promises', async ({ page }) => {
  await openPage(page);
  await page.locator('#autorun').uncheck();
  await page.locator('#preset').selectOption('quick');
  const quick = Number(await page.inputValue('#seconds'));
  const rows = ['| mesh | promised | took |', '|---|---|---|'];
  let late = 0;
  for (const file of meshes) {
    await load(page, file);
    const note = await page.locator('#time-note').textContent();
    const setup = Number(note.match(/Plus about ([\d.]+) s/)[1]);
    const runs = await page.evaluate(() => window.zomeify.runs());
    const t0 = Date.now();
    await page.locator('#run').click();
    await page.waitForFunction((n) => window.zomeify.runs() > n, runs, { timeout: 120_000, polling: 50 });
    const took = (Date.now() - t0) / 1000;
    late += took > quick + setup;
    rows.push(`| ${file} | ${quick} + ${setup} s | ${took.toFixed(1)} s |`);
  }
  console.log(rows.join('\n'));
  fs.writeFileSync(path.join(OUT, 'measure-quick.md'), rows.join('\n') + '\n');
  expect(late, 'runs past their promise').toBe(0);
});
