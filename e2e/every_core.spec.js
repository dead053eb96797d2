// Every core the browser reports can anneal: a run asked for the most threads the page offers starts
// them all (the pthread pool follows navigator.hardwareConcurrency, wasm/CMakeLists.txt), proposes on
// every one of them and ends with a valid model; "auto" leaves one core to the page.
import { test, expect } from '@playwright/test';
import { openPage, summary, waitIdle } from './support/page.js';

test('a run on every thread the page offers ends with a valid model', async ({ page }) => {
  const { info } = await openPage(page);
  const cores = await page.evaluate(() => navigator.hardwareConcurrency);
  const options = await page.locator('#threads option').allTextContents();
  expect(options[0]).toBe(`auto (${Math.max(1, Math.min(cores - 1, info.maxThreads))})`);
  expect(options.at(-1)).toBe(String(info.maxThreads));
  const p = await page.evaluate((t) => window.zomeify.run({ resolution: 6, seconds: 3, proposals: 0, threads: t }),
    info.maxThreads);
  await waitIdle(page);
  expect(p.state).toBe('done');
  expect(p.threads).toBe(info.maxThreads);
  expect(p.proposals).toBeGreaterThan(0);
  const s = await summary(page);
  expect(s.valid, s.validation).toBe(true);
});
