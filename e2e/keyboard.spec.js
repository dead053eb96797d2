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
  for (let i = 0; i < wanted + 10; i++) {
    await page.keyboard.press('Tab');
    if (await page.evaluate(() => document.activeElement?.id === 'file')) {
      // The visible button around the hidden file input shows the focus ring.
      const ring = await page.locator('label.file-button').evaluate((el) => getComputedStyle(el).outlineStyle);
      expect(ring).toBe('solid');
    }
  }
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
