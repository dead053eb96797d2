// Phones, tablets and the desktop (issue 38): at 390×844 and 768×1024 the viewer is first, at least
// 90% of the screen's width and 45% of its height; nothing scrolls sideways; every control can be
// reached (scrolling down is fine) and is not covered; at 1280×800 the three columns stay. A touch
// drag rotates the model and a pinch zooms it; a share link opened on a phone shows the model with
// the parts one tap away. Screenshots of each size go to build/e2e-results/screens-*.png.
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { PORT_NO_COI } from './playwright.config.js';
import { OUT } from './support/paths.js';
import { openPage, expectNoPageErrors } from './support/page.js';

const PHONE = { width: 390, height: 844 };
const TABLET = { width: 768, height: 1024 };
const DESKTOP = { width: 1280, height: 800 };

/** The viewer's box, the page's widths, and every control in the page that cannot be reached. */
function layout(page) {
  return page.evaluate(async () => {
    const viewer = document.getElementById('viewer').getBoundingClientRect();
    const controls = [...document.querySelectorAll('button, input, select, summary, textarea, a[href], .file-button')]
      // Shown ones only: closed <details>, hidden panels and the visually hidden file input (its
      // label is the control) are out of sight by design.
      .filter((el) => el.getClientRects().length > 0 && !el.closest('[hidden]') && !el.matches('.visually-hidden'))
      .filter((el) => el.checkVisibility() && !(el.closest('details:not([open])') && el.tagName !== 'SUMMARY'));
    const unreachable = [];
    for (const el of controls) {
      el.scrollIntoView({ block: 'center', inline: 'nearest' });
      await new Promise((resolve) => requestAnimationFrame(resolve));
      const r = el.getBoundingClientRect();
      const x = r.left + r.width / 2, y = r.top + r.height / 2;
      const top = document.elementFromPoint(x, y);
      const name = el.id || el.textContent.trim().slice(0, 20) || el.tagName;
      if (r.width < 1 || r.height < 1 || r.left < 0 || r.right > innerWidth + 0.5) unreachable.push(`${name}: off screen`);
      else if (!top || !(el.contains(top) || top.contains(el) || el.closest('label')?.contains(top))) {
        unreachable.push(`${name}: covered by ${top?.id || top?.tagName}`);
      }
    }
    window.scrollTo(0, 0);
    for (const aside of document.querySelectorAll('aside')) aside.scrollTop = 0; // the desktop's panels scroll
    return { viewer: { width: viewer.width, height: viewer.height, top: viewer.top }, controls: controls.length,
      unreachable, scrollWidth: document.documentElement.scrollWidth, innerWidth, innerHeight,
      columns: ['panel', 'results'].map((id) => document.getElementById(id).getBoundingClientRect().toJSON()) };
  });
}

async function checkScreen(page, size, url, shot) {
  await page.setViewportSize(size);
  const { errors } = await openPage(page, url);
  await page.evaluate(() => window.zomeify.warmedUp());
  const l = await layout(page);
  console.log(`screens: ${shot} viewer ${l.viewer.width.toFixed(0)}×${l.viewer.height.toFixed(0)} of ` +
    `${l.innerWidth}×${l.innerHeight}, scrollWidth ${l.scrollWidth}, ${l.controls} controls`);
  expect(l.scrollWidth, 'no sideways scrolling').toBeLessThanOrEqual(l.innerWidth);
  expect(l.unreachable, 'every control can be reached').toEqual([]);
  expect(l.controls).toBeGreaterThan(20);
  if (size.width < 900) {
    expect(l.viewer.width).toBeGreaterThanOrEqual(0.9 * size.width);
    expect(l.viewer.height).toBeGreaterThanOrEqual(0.45 * size.height);
    expect(l.viewer.top, 'the viewer comes first').toBeLessThan(1);
  } else {
    // The desktop keeps its three columns: controls left, viewer in the middle, parts right.
    const [panel, results] = l.columns;
    expect(panel.width).toBe(300);
    expect(results.width).toBe(300);
    expect(results.left).toBe(size.width - 300);
    expect(l.viewer.width).toBe(size.width - 600);
    expect(l.viewer.height).toBe(size.height);
  }
  const cover = await page.evaluate(() => window.zomeify.colourCoverage());
  expect(cover.blue + cover.yellow + cover.red, 'the model is drawn').toBeGreaterThan(0.01);
  await page.screenshot({ path: path.join(OUT, `screens-${shot}.png`) });
  await expectNoPageErrors(errors);
}

test('phone 390×844: viewer first and large, no sideways scroll, every control reachable', async ({ page }) => {
  await checkScreen(page, PHONE, '/', 'phone-390x844');
});

test('tablet 768×1024: the same', async ({ page }) => {
  await checkScreen(page, TABLET, '/', 'tablet-768x1024');
});

test('desktop 1280×800: the three columns as before', async ({ page }) => {
  await checkScreen(page, DESKTOP, '/', 'desktop-1280x800');
});

test('the single-threaded page on a phone, 390×844', async ({ page }) => {
  await checkScreen(page, PHONE, `http://127.0.0.1:${PORT_NO_COI}/`, 'phone-single-thread-390x844');
  await expect(page.locator('#fallback-note')).toBeVisible();
});

/** A one-finger drag (or, with `spread`, a two-finger pinch) over the viewer, as real touch events. */
async function touchGesture(page, { dx = 0, dy = 0, spread = 0 }) {
  const cdp = await page.context().newCDPSession(page);
  const box = await page.locator('#viewer').boundingBox();
  const cx = box.x + box.width / 2, cy = box.y + box.height / 2;
  const points = (t) => (spread
    ? [{ x: cx - 20 - spread * t, y: cy, id: 1 }, { x: cx + 20 + spread * t, y: cy, id: 2 }]
    : [{ x: cx + dx * t, y: cy + dy * t, id: 1 }]);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: points(0) });
  for (let i = 1; i <= 10; i++) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: points(i / 10) });
    await page.waitForTimeout(16);
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await page.waitForTimeout(300); // damping settles
}

const distance = (c) => Math.hypot(...c.position.map((p, i) => p - c.target[i]));

test.describe('touch', () => {
  test.use({ viewport: PHONE, hasTouch: true, isMobile: true });

  test('a touch drag rotates the model and a pinch zooms it; the canvas takes touches', async ({ page }) => {
    const { errors } = await openPage(page);
    expect(await page.evaluate(() => getComputedStyle(document.querySelector('#viewer canvas')).touchAction)).toBe('none');
    const before = await page.evaluate(() => window.zomeify.camera());
    await touchGesture(page, { dx: 120, dy: 30 });
    const turned = await page.evaluate(() => window.zomeify.camera());
    const moved = Math.hypot(...turned.position.map((p, i) => p - before.position[i]));
    expect(moved / distance(before), 'the camera orbits').toBeGreaterThan(0.1);
    expect(distance(turned)).toBeCloseTo(distance(before), 1); // a drag turns, it does not zoom
    expect(await page.evaluate(() => window.scrollY), 'the drag did not scroll the page').toBe(0);
    await touchGesture(page, { spread: 80 });
    const zoomed = await page.evaluate(() => window.zomeify.camera());
    expect(distance(zoomed), 'spreading two fingers zooms in').toBeLessThan(0.9 * distance(turned));
    await expectNoPageErrors(errors);
  });

  test('a share link opened on a phone shows the model at once, its parts one tap away', async ({ page, browser }) => {
    await openPage(page);
    const url = await page.evaluate(() => window.zomeify.shareLink());
    const phone = await (await browser.newContext({ viewport: PHONE, hasTouch: true, isMobile: true })).newPage();
    const { errors } = await openPage(phone, url);
    expect((await phone.evaluate(() => window.zomeify.summary())).source).toBe('link');
    const cover = await phone.evaluate(() => window.zomeify.colourCoverage());
    expect(cover.blue + cover.yellow + cover.red, 'the model is drawn').toBeGreaterThan(0.01);
    const viewer = await phone.locator('#viewer').boundingBox();
    expect(viewer.y).toBeLessThan(1);
    expect(viewer.height).toBeGreaterThanOrEqual(0.45 * PHONE.height);
    await expect(phone.locator('#parts-table')).not.toBeInViewport();
    await phone.locator('#to-parts').tap();
    await expect(phone.locator('#parts-table')).toBeInViewport();
    await expect(phone.locator('#kit-plan')).toContainText('Kit plan');
    await phone.screenshot({ path: path.join(OUT, 'screens-phone-link-parts.png') });
    await expectNoPageErrors(errors);
  });
});
