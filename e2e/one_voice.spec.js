// One voice (issue 38): a shape whose holes the chosen grid cannot keep: the core's answer is said
// once, nothing is ticked for the user, and the estimate, the status line and the result say the
// same thing (the case where no grid keeps them is in web/tests/controls.test.mjs: the core keeps
// the holes of every shape tried here, down to a torus with a 0.2% hole); the status line changes the moment Run is enabled again (after
// a run and after Cancel); a file that waited behind a run does not run unless "run after loading"
// is ticked, keeps the cancel message, and its name never sits beside the last shape's estimate.
import fs from 'node:fs';
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { MESHES, SHARED_MISSING } from './support/paths.js';
import { openPage, pickFile, dropFile, waitIdle, waitRunning, expectNoPageErrors } from './support/page.js';

test.skip(Boolean(SHARED_MISSING), SHARED_MISSING);

/** Records the status line each time the Run button is enabled again (the moment the run ended). */
const watchRunEnabled = (page) => page.evaluate(() => {
  window.__atEnable = [];
  const run = document.getElementById('run');
  new MutationObserver(() => {
    if (!run.disabled) window.__atEnable.push(document.getElementById('status').textContent);
  }).observe(run, { attributes: true, attributeFilter: ['disabled'] });
});

test('a grid that loses the holes: one answer in the estimate, the status and the result; nothing pre-ticked', async ({ page }) => {
  const { errors } = await openPage(page);
  await page.locator('#autorun').uncheck();
  // The grid is chosen (as a script may; the core's own choice keeps every shared mesh's holes).
  await page.evaluate(() => window.zomeify.setOptions({ resolution: 5, seconds: 1 }));
  await pickFile(page, 'eight.obj', fs.readFileSync(path.join(MESHES, 'eight.obj'))); // 2 holes
  await expect(page.locator('#surface-info')).toContainText('2 holes through it');
  await expect(page.locator('#advice')).toBeVisible({ timeout: 30_000 });
  const e = await page.evaluate(() => window.zomeify.estimate());
  expect(e.kept).toBe(false);
  expect(e.resolution).toBe(5);
  const keeps = e.advice_resolution;
  expect(keeps, 'the core names a grid that keeps them').toBeGreaterThan(5);
  // The core's sentence once, as the warning, with its button; the estimate line has the bill only.
  await expect(page.locator('#advice')).toContainText(e.advice.replace(/\.$/, ''));
  await expect(page.locator('#use-advice')).toContainText(`Use ${keeps} cells`);
  expect(await page.locator('#estimate').textContent()).not.toContain(e.advice.replace(/\.$/, ''));
  // "run anyway" is there, and not ticked: the user ticks it.
  await expect(page.locator('#genus-consent')).not.toBeChecked();
  expect(await page.locator('#panel input[type=checkbox]:checked').count()).toBe(0);
  await page.locator('#genus-consent').check();

  await watchRunEnabled(page);
  await page.locator('#run').click();
  await waitIdle(page);
  const atEnable = await page.evaluate(() => window.__atEnable);
  expect(atEnable[0], 'the status line said the run ended when Run came back').toMatch(/^Finished in [\d.]+ s\./);
  const status = await page.locator('#status').textContent();
  const result = await page.locator('#summary').textContent();
  expect(status).toContain(`but it has no hole through it where the shape has 2 holes (try ${keeps} cells)`);
  expect(result).toContain(`this model has no hole (try ${keeps} cells)`);
  // The same answer is still the one in the controls; no other resolution is named anywhere.
  await expect(page.locator('#use-advice')).toContainText(`Use ${keeps} cells`);
  const named = await page.evaluate(() => document.body.innerText.match(/\b(\d+) (?:cells|keeps)/g));
  const others = named.map((m) => Number(m.match(/\d+/)[0])).filter((n) => n !== keeps && n !== 5);
  expect(others, `resolutions named besides ${keeps} and the grid used`).toEqual([]);
  await expectNoPageErrors(errors);
});

test('Cancel: the line changes at once; a waiting file loads without a run unless asked, after the message', async ({ page }) => {
  const { errors } = await openPage(page);
  await page.locator('#autorun').uncheck();
  await page.evaluate(() => window.zomeify.warmedUp());
  await watchRunEnabled(page);
  await page.locator('#preset').selectOption('standard');
  await page.locator('#run').click();
  await waitRunning(page);
  // Keyboard focus: Run disabled itself; the focus is on Cancel, not the page body.
  await expect(page.locator('#cancel')).toBeFocused();
  await dropFile(page, 'sphere.obj', fs.readFileSync(path.join(MESHES, 'sphere.obj')));
  await expect(page.locator('#status')).toContainText('sphere.obj will load when this run ends');
  await page.evaluate(() => {
    // What the estimate line says the moment the new shape's name appears.
    window.__estimateAtName = null;
    const info = document.getElementById('surface-info');
    new MutationObserver(() => {
      if (window.__estimateAtName === null && info.textContent.startsWith('sphere.obj')) {
        window.__estimateAtName = document.getElementById('estimate').textContent;
      }
    }).observe(info, { childList: true, characterData: true, subtree: true });
  });
  const estimateBefore = await page.locator('#estimate').textContent();
  const runsBefore = await page.evaluate(() => window.zomeify.runs());
  await page.waitForTimeout(1500);
  await page.locator('#cancel').click();
  await waitIdle(page);
  expect((await page.evaluate(() => window.__atEnable))[0]).toMatch(/^Cancel/);
  await expect(page.locator('#run')).toBeFocused();
  await expect(page.locator('#surface-info')).toContainText('sphere.obj', { timeout: 20_000 });
  await expect(page.locator('#estimate')).toContainText('The model', { timeout: 20_000 });
  await page.waitForTimeout(500);
  expect(await page.evaluate(() => window.zomeify.state()), 'no run started unasked').toBe('idle');
  expect(await page.evaluate(() => window.zomeify.runs())).toBe(runsBefore + 1);
  await expect(page.locator('#status')).toContainText(/^Cancelled; kept the best model .*sphere\.obj loaded\./);
  const estimateAtName = await page.evaluate(() => window.__estimateAtName);
  expect(estimateAtName, 'the sphere never sat beside the last shape\'s estimate').not.toBe(estimateBefore);
  await expectNoPageErrors(errors);
});
