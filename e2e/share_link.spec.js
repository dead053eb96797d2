// A share link opened in a fresh page shows the same parts list, without recomputing.
import { test, expect } from '@playwright/test';
import { openPage, summary } from './support/page.js';

test('share link round trip in a fresh page', async ({ page, browser }) => {
  await openPage(page);
  const parts = await page.evaluate(() => window.zomeify.parts());
  const url = await page.evaluate(() => window.zomeify.shareLink());
  expect(url).toMatch(/#m=1\./);

  const fresh = await (await browser.newContext()).newPage();
  const { errors } = await openPage(fresh, url);
  const s = await summary(fresh);
  expect(s.source).toBe('link');
  expect(await fresh.evaluate(() => window.zomeify.progress())).toBeNull(); // nothing was run
  expect(await fresh.evaluate(() => window.zomeify.parts())).toEqual(parts);
  expect(errors).toEqual([]);
});

test('a damaged link gives a clear message and a model is still shown', async ({ page }) => {
  await openPage(page, '/#m=1.AAAA_broken');
  await expect(page.locator('#status')).toHaveClass(/error/);
  await expect(page.locator('#status')).toContainText('share link');
  const s = await summary(page);
  expect(s.balls).toBeGreaterThan(0);
});
