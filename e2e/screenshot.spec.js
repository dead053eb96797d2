// The finished model on screen is not blank and shows all three strut colours (pixel test).
// The screenshot is kept in build/e2e-results/model.png for a person to look at.
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { OUT } from './support/paths.js';
import { openPage } from './support/page.js';

test('screenshot shows blue, yellow and red struts', async ({ page }) => {
  await openPage(page);
  await page.waitForTimeout(500); // a few frames after the fit
  await page.locator('#viewer').screenshot({ path: path.join(OUT, 'model.png') });
  const c = await page.evaluate(() => window.zomeify.colourCoverage());
  expect(c.background, JSON.stringify(c)).toBeLessThan(0.97);
  expect(c.blue, JSON.stringify(c)).toBeGreaterThan(0.002);
  expect(c.yellow, JSON.stringify(c)).toBeGreaterThan(0.002);
  expect(c.red, JSON.stringify(c)).toBeGreaterThan(0.002);
});
