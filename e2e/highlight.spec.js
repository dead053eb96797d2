// Hovering a row of the parts table highlights those struts in the viewer (and only while hovered).
import { test, expect } from '@playwright/test';
import { openPage } from './support/page.js';

test('hovering a parts row highlights its struts', async ({ page }) => {
  await openPage(page);
  const before = await page.evaluate(() => window.zomeify.colourCoverage());
  expect(before.highlight).toBeLessThan(0.0005);
  await page.hover('#parts-table tr[data-kind="B1"]');
  await expect.poll(async () => (await page.evaluate(() => window.zomeify.colourCoverage())).highlight)
    .toBeGreaterThan(0.002);
  const during = await page.evaluate(() => window.zomeify.colourCoverage());
  expect(during.yellow).toBeLessThan(before.yellow / 2); // the others are dimmed
  await page.mouse.move(5, 5);
  await expect.poll(async () => (await page.evaluate(() => window.zomeify.colourCoverage())).highlight)
    .toBeLessThan(0.0005);
});
