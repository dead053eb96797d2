// Working on the model on screen (issue 40), in the threaded and the single-threaded page: from the
// torus sample, Fewer balls, More detail, Fix the largest gap and Fix here (a click on the shape
// chooses the spot) continue the model (the buttons and window.zomeify.workOn), Undo puts back the
// model before each, Improve never ends worse, and a share link of a continued model opens with the
// same parts.
import { test, expect } from '@playwright/test';
import { PORT_NO_COI } from './playwright.config.js';
import { openPage, summary, waitIdle, expectNoPageErrors } from './support/page.js';

const PAGES = [['threaded', '/'], ['single-threaded', `http://127.0.0.1:${PORT_NO_COI}/`]];

for (const [name, url] of PAGES) {
  test(`${name}: Fewer balls, More detail, Fix the largest gap, Improve and Undo`, async ({ page, browser }) => {
    test.setTimeout(180_000);
    const { errors } = await openPage(page, url);
    await page.evaluate(() => window.zomeify.setOptions({ proposals: 150000, threads: 1 }));
    const sample = await summary(page);
    await expect(page.locator('#work-fewer')).toBeEnabled();
    await expect(page.locator('#work-undo')).toBeDisabled();

    // Fewer balls by its button: the same size, about 25 % fewer balls, the same holes.
    const runs = await page.evaluate(() => window.zomeify.runs());
    await page.locator('#work-fewer').click();
    await page.waitForFunction((n) => window.zomeify.runs() > n, runs, { timeout: 90_000 });
    await waitIdle(page);
    const fewer = await summary(page);
    expect(fewer.valid, fewer.validation).toBe(true);
    expect(fewer.genus).toBe(sample.genus);
    expect(fewer.balls).toBeLessThan(0.9 * sample.balls);
    expect(fewer.stats.b1_mesh_units).toBeCloseTo(sample.stats.b1_mesh_units, 9);
    await expect(page.locator('#work-note')).toContainText(`Fewer balls: ${sample.balls} → ${fewer.balls} balls`);
    await expect(page.locator('#work-undo')).toBeEnabled();

    // More detail, then Fix the largest gap, through the API.
    const more = await page.evaluate(() => window.zomeify.workOn('more'));
    expect(more.state).toBe('done');
    const detailed = await summary(page);
    expect(detailed.balls).toBeGreaterThan(fewer.balls);
    const gapBefore = detailed.stats.fidelity.hausdorff_mm;
    await page.evaluate(() => window.zomeify.workOn('fix'));
    const fixed = await summary(page);
    expect(fixed.valid, fixed.validation).toBe(true);
    const region = fixed.stats.continued.region;
    expect(region.largest_gap_b0_after).toBeLessThanOrEqual(region.largest_gap_b0_before);
    console.log(`${name}: ${sample.balls} → fewer ${fewer.balls} → more ${detailed.balls} (gap ${gapBefore.toFixed(0)} mm)` +
      ` → fix: gap within the spot ${(region.largest_gap_b0_before * 46.27).toFixed(0)} → ` +
      `${(region.largest_gap_b0_after * 46.27).toFixed(0)} mm`);

    // Fix here: a click on the shape (not a drag) chooses the spot, then the button.
    const canvas = await page.locator('#viewer canvas').boundingBox();
    for (const fx of [0.3, 0.7, 0.4, 0.6, 0.5]) {
      await page.mouse.click(canvas.x + fx * canvas.width, canvas.y + 0.5 * canvas.height);
      if (await page.evaluate(() => window.zomeify.spot())) break;
    }
    expect(await page.evaluate(() => window.zomeify.spot()), 'a click on the torus chose a spot').not.toBeNull();
    await expect(page.locator('#work-note')).toContainText('Spot chosen: Fix here changes only the model within');
    const runsHere = await page.evaluate(() => window.zomeify.runs());
    await page.locator('#work-here').click();
    await page.waitForFunction((n) => window.zomeify.runs() > n, runsHere, { timeout: 90_000 });
    await waitIdle(page);
    const here = await summary(page);
    expect(here.valid, here.validation).toBe(true);
    expect(here.stats.continued.region.balls).toBeGreaterThan(0);
    await page.evaluate(() => window.zomeify.undo());
    expect((await summary(page)).balls).toBe(fixed.balls);

    // A share link of the continued model opens with its parts.
    const link = await page.evaluate(() => window.zomeify.shareLink());
    const fresh = await (await browser.newContext()).newPage();
    await openPage(fresh, link);
    const opened = await summary(fresh);
    expect([opened.balls, opened.struts]).toEqual([fixed.balls, fixed.struts]);

    // Undo, three times: back through the fix and More detail to Fewer balls, then the sample.
    await page.evaluate(() => window.zomeify.undo());
    expect((await summary(page)).balls).toBe(detailed.balls);
    await page.evaluate(() => window.zomeify.undo());
    expect((await summary(page)).balls).toBe(fewer.balls);
    await page.locator('#work-undo').click();
    await page.waitForFunction((n) => document.getElementById('work-note').textContent.includes(`(${n} balls)`),
      sample.balls, { timeout: 20_000 });
    const back = await summary(page);
    expect([back.balls, back.struts]).toEqual([sample.balls, sample.struts]);
    await expect(page.locator('#work-undo')).toBeDisabled();

    // Improve: the same balls, never a higher energy than the model it started from.
    await page.evaluate(() => window.zomeify.workOn('improve'));
    const improved = await summary(page);
    expect(improved.valid, improved.validation).toBe(true);
    expect(improved.stats.energy.end.total).toBeLessThanOrEqual(improved.stats.energy.start.total + 1e-9);
    await expectNoPageErrors(errors);
  });
}
