// A share link opened in a fresh page shows the same parts list, without recomputing.
import { test, expect } from '@playwright/test';
import { openPage, summary } from './support/page.js';

test('share link round trip in a fresh page', async ({ page, browser }) => {
  await openPage(page);
  const parts = await page.evaluate(() => window.zomeify.parts());
  const url = await page.evaluate(() => window.zomeify.shareLink());
  expect(url).toMatch(/#m=2\./);

  const fresh = await (await browser.newContext()).newPage();
  const { errors } = await openPage(fresh, url);
  const s = await summary(fresh);
  expect(s.source).toBe('link');
  expect(await fresh.evaluate(() => window.zomeify.progress())).toBeNull(); // nothing was run
  const back = await fresh.evaluate(() => window.zomeify.parts());
  // Node order differs after a round trip, so float sums may differ in their last bits.
  for (const key of ['total_strut_length_b0', 'total_strut_length_mm']) {
    expect(back[key]).toBeCloseTo(parts[key], 6);
    delete back[key];
    delete parts[key];
  }
  expect(back).toEqual(parts);
  expect(errors).toEqual([]);
});

test('a damaged link gives a clear message and a model is still shown', async ({ page }) => {
  await openPage(page, '/#m=1.AAAA_broken');
  await expect(page.locator('#status')).toHaveClass(/error/);
  await expect(page.locator('#status')).toContainText('share link');
  const s = await summary(page);
  expect(s.balls).toBeGreaterThan(0);
});
