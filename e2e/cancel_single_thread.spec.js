// Cancel in the single-threaded page (no COOP/COEP): the run blocks the core's worker, so the page
// ends that worker and starts a fresh one with the mesh and the last checkpoint of the model
// (web/src/bridge.js). Idle within 0.5 s, a valid model kept, a second run works.
import { test, expect } from '@playwright/test';
import { PORT_NO_COI } from './playwright.config.js';
import { openPage, summary, waitRunning, waitIdle, clickCancelTimed, expectNoPageErrors } from './support/page.js';

test('single-threaded: cancel within 0.5 s keeps a valid model, then a second run', async ({ page }) => {
  const { info, errors } = await openPage(page, `http://127.0.0.1:${PORT_NO_COI}/`);
  expect(info.threaded).toBe(false);
  await page.evaluate(() => { window.__run = window.zomeify.run({ resolution: 8, seconds: 120, proposals: 0 }); });
  await waitRunning(page);
  await page.waitForFunction(() => window.zomeify.progress()?.state === 'annealing', null, { timeout: 30_000 });
  await page.waitForTimeout(2500); // past the first checkpoints
  const ballsShown = await page.evaluate(() => window.zomeify.progress().nodes);
  const ms = await clickCancelTimed(page);
  console.log(`single-threaded cancel: idle ${ms.toFixed(0)} ms after the click`);
  expect(ms, `cancel took ${ms.toFixed(0)} ms`).toBeLessThan(500);
  const final = await page.evaluate(() => window.zomeify.progress());
  expect(final.state).toBe('cancelled');
  expect(final.fraction).toBeLessThan(0.5); // the bar shows how far the run got, not full
  const kept = await summary(page); // answered by the fresh worker
  expect(kept.valid, kept.validation).toBe(true);
  expect(kept.balls).toBeGreaterThan(0.5 * ballsShown);
  await expect(page.locator('#status')).toContainText('Cancelled');

  const second = await page.evaluate(() => window.zomeify.run({ resolution: 8, seconds: 2 }));
  await waitIdle(page);
  expect(second.state).toBe('done');
  const s = await summary(page);
  expect(s.valid, s.validation).toBe(true);
  expect(s.source).toBe('run');
  await expectNoPageErrors(errors);
});
