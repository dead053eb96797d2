// Cancel returns to idle within 0.5 s and keeps a valid model; a second run works.
import { test, expect } from '@playwright/test';
import { openPage, summary, waitRunning, waitIdle, clickCancelTimed } from './support/page.js';

test('cancel within 0.5 s keeps a valid model, then a second run', async ({ page }) => {
  await openPage(page);
  await page.evaluate(() => { window.__run = window.zomeify.run({ resolution: 8, seconds: 120, proposals: 0 }); });
  await waitRunning(page);
  await page.waitForFunction(() => window.zomeify.progress()?.state === 'annealing', null, { timeout: 30_000 });
  await page.waitForTimeout(1000);
  const ms = await clickCancelTimed(page);
  console.log(`cancel: idle ${ms.toFixed(0)} ms after the click`);
  expect(await page.evaluate(() => window.zomeify.state())).toBe('idle');
  expect(await page.evaluate(() => window.zomeify.progress().state)).toBe('cancelled');
  expect(ms, `cancel took ${ms.toFixed(0)} ms`).toBeLessThan(500);
  const kept = await summary(page);
  expect(kept.valid, kept.validation).toBe(true);
  expect(kept.balls).toBeGreaterThan(0);

  const second = await page.evaluate(() => window.zomeify.run({ resolution: 8, seconds: 2 }));
  await waitIdle(page);
  expect(second.state).toBe('done');
  const s = await summary(page);
  expect(s.valid, s.validation).toBe(true);
});
