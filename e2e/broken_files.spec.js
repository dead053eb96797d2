// Broken files give a clear message and leave the previous model on screen.
import { test, expect } from '@playwright/test';
import { SHARED_MISSING } from './support/paths.js';
import { openPage, summary, dropFile } from './support/page.js';

test.skip(Boolean(SHARED_MISSING), SHARED_MISSING);

function randomBytes(n, seed) {
  const out = new Uint8Array(n);
  let x = seed;
  for (let i = 0; i < n; i++) {
    x = (x * 1103515245 + 12345) >>> 0;
    out[i] = x >>> 24;
  }
  return out;
}

// A real PNG header (8-byte signature, IHDR chunk) followed by noise.
const png = new Uint8Array([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0, 0, 0, 13, 0x49, 0x48, 0x44, 0x52,
  0, 0, 0, 16, 0, 0, 0, 16, 8, 6, 0, 0, 0, ...randomBytes(200, 3)]);

// A single quad: an open sheet with no inside (a mesh with a few holes is repaired instead: wild_mesh.spec.js).
const sheet = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n';

const cases = [
  ['random bytes named .obj', 'noise.obj', randomBytes(4096, 1), /noise\.obj/],
  ['an empty file', 'empty.stl', new Uint8Array(0), /empty.stl: .*empty/],
  ['a PNG renamed .stl', 'picture.stl', png, /picture\.stl/],
  ['an open sheet', 'sheet.obj', new TextEncoder().encode(sheet), /sheet\.obj: mesh is an open sheet, not a solid/],
];

for (const [what, name, bytes, pattern] of cases) {
  test(`${what}: clear message, previous model stays`, async ({ page }) => {
    const { errors } = await openPage(page);
    const before = await summary(page);
    await dropFile(page, name, bytes);
    await expect(page.locator('#status')).toHaveClass(/error/);
    const message = await page.locator('#status').textContent();
    expect(message).toMatch(pattern);
    expect(message.length).toBeLessThan(400);
    expect(message).not.toMatch(/\n/);
    expect(await page.evaluate(() => window.zomeify.state())).toBe('idle');
    const after = await summary(page);
    expect(after).toEqual(before);
    expect(errors).toEqual([]);
  });
}
