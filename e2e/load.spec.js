// The page loads cross-origin isolated with the threaded build and shows the finished sample.
import { test, expect } from '@playwright/test';
import { openPage, summary, expectNoPageErrors } from './support/page.js';

test('cross-origin isolated, threaded build, sample model shown within 3 s', async ({ page }) => {
  const { info, ms, errors } = await openPage(page);
  expect(info.crossOriginIsolated).toBe(true);
  expect(info.threaded).toBe(true);
  // The pthread pool follows the cores the browser reports: 2 to 16 annealing threads.
  const cores = await page.evaluate(() => navigator.hardwareConcurrency);
  expect(info.maxThreads).toBe(Math.max(2, Math.min(16, cores)));
  const s = await summary(page);
  expect(s.balls).toBeGreaterThan(0);
  expect(s.struts).toBeGreaterThan(0);
  expect(s.source).toBe('file'); // the precomputed sample, not a run
  // performance.now() counts from the navigation's start.
  console.log(`load: sample drawn at ${info.firstModelMs.toFixed(0)} ms, core ready with the sample at ${info.readyMs.toFixed(0)} ms`);
  expect(info.firstModelMs, `sample model drawn after ${info.firstModelMs?.toFixed(0)} ms; core ready and ` +
    `the sample loaded into it after ${info.readyMs?.toFixed(0)} ms (test saw ${ms} ms)`).toBeLessThan(3000);
  const c = await page.evaluate(() => window.zomeify.colourCoverage());
  expect(c.background).toBeLessThan(0.99); // something is drawn
  await expect(page.locator('#fallback-note')).toBeHidden();
  await expect(page.locator('#parts-table tr')).not.toHaveCount(0);
  await expectNoPageErrors(errors);
});
