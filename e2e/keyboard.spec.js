// Keyboard access (issue 26, item 6): Tab reaches every control in sight, the file picker first
// among them, each with a visible focus ring; a focused parts row highlights its struts as hover does.
import { test, expect } from '@playwright/test';
import { openPage, expectNoPageErrors } from './support/page.js';

test('Tab reaches every control in sight, with a visible focus', async ({ page }) => {
  const { errors } = await openPage(page);
  await expect(page.locator('#parts-table tr[data-kind]')).not.toHaveCount(0);
  // The controls a user can see and use: visible, enabled, not inside a closed <details> (its
  // summary counts), and the file input whose label is the visible button.
  const wanted = await page.evaluate(() => {
    window.__reached = new Set();
    document.addEventListener('focusin', (e) => window.__reached.add(e.target));
    const all = [...document.querySelectorAll('button, input, select, summary, [tabindex="0"]')];
    window.__wanted = all.filter((el) => !el.disabled && (el.id === 'file' || el.checkVisibility())
      && !(el.closest('details:not([open])') && el.tagName !== 'SUMMARY'));
    return window.__wanted.length;
  });
  expect(wanted).toBeGreaterThan(20);
  const ringless = [];
  for (let i = 0; i < wanted + 10; i++) {
    await page.keyboard.press('Tab');
    // A focus ring on the element, or for the hidden file input on the visible button around it.
    const missing = await page.evaluate(() => {
      const el = document.activeElement;
      if (!el || el === document.body) return null; // past the last control: the browser's own UI
      const shown = el.id === 'file' ? el.closest('label') : el;
      const style = getComputedStyle(shown);
      return style.outlineStyle === 'none' || parseFloat(style.outlineWidth) < 1 ? el.id || el.tagName : null;
    });
    if (missing) ringless.push(missing);
  }
  expect(ringless, 'focused without a visible ring').toEqual([]);
  const missed = await page.evaluate(() => window.__wanted.filter((el) => !window.__reached.has(el))
    .map((el) => el.id || el.dataset.kind || el.dataset.format || el.textContent.trim().slice(0, 20)));
  expect(missed).toEqual([]);
  expect(await page.evaluate(() => window.__reached.has(document.getElementById('file')))).toBe(true);
  await expectNoPageErrors(errors);
});

test('a parts row focused with the keyboard highlights its struts', async ({ page }) => {
  await openPage(page);
  const row = page.locator('#parts-table tr[data-kind="B1"]');
  await row.focus();
  await expect.poll(async () => (await page.evaluate(() => window.zomeify.colourCoverage())).highlight)
    .toBeGreaterThan(0.002);
  expect(await row.evaluate((el) => getComputedStyle(el).outlineStyle)).toBe('solid');
  await page.locator('#fit').focus(); // focus leaves the table
  await expect.poll(async () => (await page.evaluate(() => window.zomeify.colourCoverage())).highlight)
    .toBeLessThan(0.0005);
});
