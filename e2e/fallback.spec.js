// Served without COOP/COEP, the single-threaded build runs the pipeline to the end, with a note.
import { test, expect } from '@playwright/test';
import { PORT_NO_COI } from './playwright.config.js';
import { openPage, summary } from './support/page.js';

test('no COOP/COEP: single-threaded build, visible note, a whole run', async ({ page }) => {
  const { info, errors } = await openPage(page, `http://127.0.0.1:${PORT_NO_COI}/`);
  expect(info.crossOriginIsolated).toBe(false);
  expect(info.threaded).toBe(false);
  await expect(page.locator('#fallback-note')).toBeVisible();
  const final = await page.evaluate(() => window.zomeify.run({ resolution: 8, seconds: 3, threads: 1 }));
  expect(final.state).toBe('done');
  expect(final.annealer).toBe(true);
  const s = await summary(page);
  expect(s.source).toBe('run');
  expect(s.valid, s.validation).toBe(true);
  expect(errors).toEqual([]);
});
