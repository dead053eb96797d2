// The main panel in plain words (issue 26, items 3 and 9): a run that closed the shape's holes says
// so and names a resolution that keeps them, and that resolution does; no technical term (Z0,
// valid, genus, b0, temperature/energy figures, COOP/COEP) is in the visible text, only behind
// "technical details".
import fs from 'node:fs';
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { PORT_NO_COI } from './playwright.config.js';
import { MESHES, SHARED_MISSING } from './support/paths.js';
import { openPage, pickFile, expectNoPageErrors } from './support/page.js';

test.skip(Boolean(SHARED_MISSING), SHARED_MISSING);

// Case matters: "B0" is a blue strut's name, "b0" the unit of length.
const JARGON = /\bZ0\b|\b[Vv]alid\b|\b[Gg]enus\b|\bb0\b|COOP|COEP|\bT \d|\bE \d|E_dist|[Cc]ross-origin/;

/** The text a user sees (closed <details> are not rendered, so innerText leaves them out). */
const visibleText = (page) => page.evaluate(() => document.body.innerText);

/** The first technical term in sight, with the words around it; null when there is none. */
function jargonIn(text) {
  const m = JARGON.exec(text);
  return m && text.slice(Math.max(0, m.index - 60), m.index + 40);
}

test('a lost hole names a resolution that keeps it, and that resolution does', async ({ page }) => {
  const { errors } = await openPage(page);
  await page.locator('#autorun').uncheck();
  await pickFile(page, 'eight.obj', fs.readFileSync(path.join(MESHES, 'eight.obj'))); // 2 holes
  await expect(page.locator('#surface-info')).toContainText('eight.obj');
  await page.evaluate(() => window.zomeify.run({ resolution: 5, seconds: 1, threads: 1 }));
  const summary = page.locator('#summary');
  await expect(summary).toContainText(/this model has no hole \(try \d+ cells\)/);
  const cells = Number((await summary.textContent()).match(/try (\d+) cells/)[1]);
  expect(cells).not.toBe(5);
  await expect(page.locator('#status')).toContainText(`(try ${cells} cells)`);
  expect(jargonIn(await visibleText(page))).toBeNull();
  await expect(page.locator('#quality-tech')).toContainText('genus 0');

  await page.evaluate((r) => window.zomeify.run({ resolution: r, seconds: 1, threads: 1 }), cells);
  await expect(summary).toContainText('a closed surface with the shape\'s holes');
  await expectNoPageErrors(errors);
});

test('no technical terms in sight on the single-threaded page after a run', async ({ page }) => {
  const { errors } = await openPage(page, `http://127.0.0.1:${PORT_NO_COI}/`);
  await expect(page.locator('#fallback-note')).toBeVisible();
  await page.evaluate(() => window.zomeify.run({ resolution: 8, seconds: 2 }));
  await expect(page.locator('#quality')).toContainText('Largest gap');
  const text = await visibleText(page);
  expect(text).toContain('Finished');
  expect(jargonIn(text)).toBeNull();
  await page.locator('#results details summary').click(); // one click away
  await expect(page.locator('#quality-tech')).toBeVisible();
  expect(await visibleText(page)).toMatch(/genus 1\b.*b0/s);
  await expectNoPageErrors(errors);
});
