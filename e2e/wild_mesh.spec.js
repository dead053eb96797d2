// A mesh from the wild (issue 36): a torus with three holes punched in it, made here in code, is
// dropped as it is. The page lists the repairs before the run ("closed 3 holes ...") and the run
// ends with a valid model that keeps the torus's one hole.
import { test, expect } from '@playwright/test';
import { openPage, pickFile, summary, expectNoPageErrors } from './support/page.js';

/** OBJ of a torus (tube radius r round a circle of radius R) less the quads near three points. */
function holedTorusObj(R = 2, r = 0.8, nu = 48, nv = 24) {
  const v = [];
  const f = [];
  for (let i = 0; i < nu; i++) {
    for (let j = 0; j < nv; j++) {
      const a = (2 * Math.PI * i) / nu;
      const b = (2 * Math.PI * j) / nv;
      v.push([(R + r * Math.cos(b)) * Math.cos(a), r * Math.sin(b), (R + r * Math.cos(b)) * Math.sin(a)]);
    }
  }
  const at = (i, j) => (i % nu) * nv + (j % nv) + 1;
  const holes = [[0, 0], [16, 6], [32, 12]]; // (i, j) of each hole's centre quad
  for (let i = 0; i < nu; i++) {
    for (let j = 0; j < nv; j++) {
      const inHole = holes.some(([hi, hj], k) => Math.abs(i - hi) <= k && Math.abs(j - hj) <= k);
      if (!inHole) f.push([at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)]);
    }
  }
  return v.map((p) => `v ${p.join(' ')}`).join('\n') + '\n' + f.map((q) => `f ${q.join(' ')}`).join('\n') + '\n';
}

test('a torus with three holes is repaired, the repairs are shown, and the model keeps its hole', async ({ page }) => {
  const { errors } = await openPage(page);
  await page.evaluate(() => window.zomeify.setOptions({ seconds: 2 }));
  const runsBefore = await page.evaluate(() => window.zomeify.runs());
  await pickFile(page, 'holed_torus.obj', new TextEncoder().encode(holedTorusObj())); // "run after loading" is ticked
  // Before the run ends (it takes at least its 2 s), the repairs are on screen.
  await expect(page.locator('#surface-info')).toContainText('holed_torus.obj', { timeout: 20_000 });
  const before = await page.locator('#surface-info').textContent();
  expect(before).toMatch(/repaired: .*closed 3 holes \(4, 12 and 20 edges\)/);
  expect(await page.evaluate(() => window.zomeify.state())).not.toBe('error');
  await page.waitForFunction((n) => window.zomeify.runs() > n && window.zomeify.state() === 'idle', runsBefore,
    { timeout: 120_000, polling: 100 });
  const progress = await page.evaluate(() => window.zomeify.progress());
  const s = await summary(page);
  expect(progress.state).toBe('done');
  expect(s.valid, s.validation).toBe(true);
  expect(progress.surface_genus).toBe(1);
  expect(progress.genus).toBe(1);
  await expectNoPageErrors(errors);
});

/** OBJ of rolling hills over a square: an open sheet, refused until it is given a thickness. */
function terrainObj(n = 16) {
  const v = [];
  const f = [];
  for (let i = 0; i <= n; i++) {
    for (let j = 0; j <= n; j++) v.push([i / n, j / n, 0.15 * Math.sin(3 * i / n) * Math.cos(4 * j / n)]);
  }
  const at = (i, j) => i * (n + 1) + j + 1;
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) f.push([at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
  }
  return v.map((p) => `v ${p.join(' ')}`).join('\n') + '\n' + f.map((q) => `f ${q.join(' ')}`).join('\n') + '\n';
}

test('a terrain patch is refused as an open sheet, and "Give it a thickness" makes a model of it', async ({ page }) => {
  const { errors } = await openPage(page);
  await page.evaluate(() => window.zomeify.setOptions({ seconds: 1 }));
  const before = await summary(page);
  await pickFile(page, 'terrain.obj', new TextEncoder().encode(terrainObj()));
  const status = page.locator('#status');
  await expect(status).toHaveClass(/error/, { timeout: 20_000 });
  await expect(status).toContainText('terrain.obj: mesh is an open sheet, not a solid');
  expect(await summary(page)).toEqual(before); // the model on screen stays
  const runsBefore = await page.evaluate(() => window.zomeify.runs());
  await status.getByRole('button', { name: 'Give it a thickness' }).click();
  await expect(page.locator('#surface-info')).toContainText('gave the open sheet a thickness', { timeout: 20_000 });
  await page.waitForFunction((n) => window.zomeify.runs() > n && window.zomeify.state() === 'idle', runsBefore,
    { timeout: 120_000, polling: 100 });
  const s = await summary(page);
  expect(s.valid, s.validation).toBe(true);
  expect((await page.evaluate(() => window.zomeify.progress())).genus).toBe(0);
  await expectNoPageErrors(errors);
});
