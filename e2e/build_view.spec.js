// The Build view (issue 24): step through the sample's assembly to the end (the steps' parts add
// up to the parts list), a middle step's struts glow in another colour than the built ones, the
// print view has a panel per step; and the CLI's steps page opens with no network request.
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { test, expect } from '@playwright/test';
import { MESHES, OUT, SHARED_MISSING } from './support/paths.js';
import { cli } from './support/cli.js';
import { openPage } from './support/page.js';

test.skip(Boolean(SHARED_MISSING), SHARED_MISSING);

const coverage = (page) => page.evaluate(() => window.zomeify.colourCoverage());

test('build view: every step, a highlighted middle step, the print view', async ({ page }) => {
  await openPage(page);
  const report = await page.evaluate(() => window.zomeify.parts());
  await page.click('#build-toggle');
  await expect(page.locator('#build-text')).toContainText('Step 1 of');
  const steps = Number(await page.locator('#build-step').getAttribute('max'));
  expect(steps).toBeGreaterThan(3);

  // Step to the end with the next key, adding up each step's parts as the panel lists them.
  let balls = 0, struts = 0;
  for (let k = 0; k < steps; k++) {
    await expect(page.locator('#build-text')).toContainText(`Step ${k + 1} of ${steps}`);
    for (const line of await page.locator('#build-parts li').allTextContents()) {
      const [count, code] = line.split(' × ');
      if (code === report.ball_part_code) balls += Number(count);
      else struts += Number(count);
    }
    await page.keyboard.press('ArrowRight');
  }
  expect(balls).toBe(report.balls);
  expect(struts).toBe(report.strut_count);
  await expect(page.locator('#build-totals')).toHaveText(
    `Built so far: ${report.balls} of ${report.balls} balls, ${report.strut_count} of ${report.strut_count} struts.`);
  await page.keyboard.press('ArrowLeft');
  await expect(page.locator('#build-text')).toContainText(`Step ${steps - 1} of ${steps}`);

  // A middle step: its struts glow green, the built ones keep their colours.
  const mid = Math.floor(steps / 2);
  await page.evaluate((k) => window.zomeify.buildStep(k), mid);
  // A step of a few struts may sit behind others: some tens of green pixels are enough.
  await expect.poll(async () => (await coverage(page)).highlight).toBeGreaterThan(0.00004);
  const c = await coverage(page);
  expect(c.blue + c.yellow + c.red, JSON.stringify(c)).toBeGreaterThan(0.001);
  await page.locator('#viewer').screenshot({ path: path.join(OUT, 'build-step.png') });

  // The print view: one panel per step, the last one named.
  await page.click('#build-print');
  const frame = page.frameLocator('#print-frame');
  await expect(frame.locator('section.step')).toHaveCount(steps);
  await expect(frame.locator(`#step-${steps} h2`)).toHaveText(`Step ${steps} of ${steps}`);
  await expect(frame.locator('section.step svg').first()).toBeVisible();
  await page.click('#print-close');

  // Closing the view restores the model's colours.
  await page.click('#build-toggle');
  await expect(page.locator('#build-panel')).toBeHidden();
  await page.mouse.move(5, 5); // off the parts rows, whose hover highlights too
  await expect.poll(async () => (await coverage(page)).highlight).toBeLessThan(c.highlight / 4);
});

test('the steps page of the CLI opens with no network request', async ({ page }) => {
  fs.mkdirSync(OUT, { recursive: true });
  const file = path.join(OUT, 'steps.html');
  const model = path.join(MESHES, '..', 'vef', 'bunny.vef');
  cli(['steps', model, '-o', file]);
  const url = pathToFileURL(file).href;
  const requests = [];
  page.on('request', (r) => { if (r.url() !== url) requests.push(r.url()); });
  await page.goto(url);
  await expect(page.locator('section.step').first()).toBeVisible();
  expect(await page.locator('section.step svg line').count()).toBeGreaterThan(10); // each step's own struts
  expect(requests).toEqual([]);
});
