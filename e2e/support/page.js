// Helpers shared by the specs: open the page, wait for it, drop or pick files, wait for runs.
import { expect } from '@playwright/test';

/** Opens the page and waits until window.zomeify.ready resolved; returns {info, ms}. */
export async function openPage(page, url = '/') {
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  const t0 = Date.now();
  await page.goto(url);
  const info = await page.evaluate(async () => window.zomeify.ready);
  return { info, ms: Date.now() - t0, errors };
}

export async function summary(page) {
  return page.evaluate(() => window.zomeify.summary());
}

/** Dispatches a real drop event carrying `bytes` as a file named `name` on the page. */
export async function dropFile(page, name, bytes) {
  const dataTransfer = await page.evaluateHandle(({ name, data }) => {
    const dt = new DataTransfer();
    dt.items.add(new File([new Uint8Array(data)], name));
    return dt;
  }, { name, data: [...bytes] });
  await page.dispatchEvent('body', 'drop', { dataTransfer });
}

export async function pickFile(page, name, bytes) {
  await page.locator('#file').setInputFiles({ name, mimeType: 'application/octet-stream', buffer: Buffer.from(bytes) });
}

/** Waits until the page is idle again after a run was started (by UI or API). */
export async function waitIdle(page, timeout = 90_000) {
  await page.waitForFunction(() => window.zomeify.state() === 'idle', null, { timeout, polling: 50 });
}

export async function waitRunning(page, timeout = 20_000) {
  await page.waitForFunction(() => window.zomeify.state() === 'running', null, { timeout, polling: 20 });
}

export async function expectNoPageErrors(errors) {
  expect(errors, 'uncaught errors on the page').toEqual([]);
}

/** Clicks Cancel during the run started as window.__run; ms until the page is idle again. */
export async function clickCancelTimed(page) {
  return page.evaluate(async () => {
    const t0 = performance.now();
    document.getElementById('cancel').click();
    while (window.zomeify.state() !== 'idle') await new Promise((resolve) => setTimeout(resolve, 5));
    const idle = performance.now() - t0;
    await window.__run;
    return idle;
  });
}
