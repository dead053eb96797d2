// Issue 38's small items: no request of a page load is a 404 (the favicon is served, as an icon);
// the two VEF buttons save under different names; a share link carries the model's resolution and
// the page it opens shows it on the slider; the kits before a run are the core's range, one kit
// sentence beside the finished sample (its plan under Parts); the time preset says what it does
// not count.
import { test, expect } from '@playwright/test';
import { openPage, expectNoPageErrors } from './support/page.js';

test('favicon served, no 404 on load; two VEF names; a link shows its model\'s resolution', async ({ page, browser }) => {
  const missing = [];
  page.on('response', (r) => { if (r.status() >= 400) missing.push(`${r.status()} ${r.url()}`); });
  const { errors } = await openPage(page);
  await page.evaluate(() => window.zomeify.warmedUp());
  const ico = await page.request.get('/favicon.ico');
  expect(ico.status()).toBe(200);
  expect(ico.headers()['content-type']).toBe('image/x-icon');
  expect((await ico.body()).readUInt16LE(2), 'an ICO file').toBe(1);
  expect(missing).toEqual([]);

  const names = [];
  for (const format of ['vef', 'vef-struts']) {
    const [download] = await Promise.all([page.waitForEvent('download'), page.click(`[data-format=${format}]`)]);
    names.push(download.suggestedFilename());
  }
  expect(names).toEqual(['torus.vef', 'torus-no-panels.vef']);

  // The sample was made at 8 cells; the slider's own default is 12.
  expect(await page.inputValue('#resolution')).toBe('8');
  const url = await page.evaluate(() => window.zomeify.shareLink());
  expect(url).toMatch(/#m=2\.[^&]+&r=8$/);
  const fresh = await (await browser.newContext()).newPage();
  await openPage(fresh, url);
  expect((await fresh.evaluate(() => window.zomeify.summary())).source).toBe('link');
  expect(await fresh.inputValue('#resolution')).toBe('8');
  await expect(fresh.locator('#resolution-value')).toHaveText('8');
  await expectNoPageErrors(errors);
});

test('one kit sentence per model: beside the finished sample only its plan names kits', async ({ page }) => {
  const { errors } = await openPage(page);
  await expect(page.locator('#kit-plan')).toContainText('Kit plan:');
  await expect(page.locator('#estimate')).toHaveText(/made at 8 cells; its parts and kit plan are under Parts/);
  const kitSentences = await page.evaluate(() => document.body.innerText.match(/Creator|Basic|Workshop/g)?.length ?? 0);
  const planKits = await page.evaluate(() => document.getElementById('kit-plan').innerText.match(/Creator|Basic|Workshop/g).length);
  expect(kitSentences, 'no kit named outside the kit plan (and the picker\'s labels, closed)').toBe(planKits);
  // Another resolution is another model: its estimate names the core's range, safe end last.
  await page.locator('#resolution').fill('10');
  await expect(page.locator('#estimate')).toContainText('kits:', { timeout: 20_000 });
  const e = await page.evaluate(() => window.zomeify.estimate());
  expect(e.kit_plan_parts).toBeGreaterThan(0);
  await expect(page.locator('#estimate')).toContainText(e.kit_plan);
  await expectNoPageErrors(errors);
});
