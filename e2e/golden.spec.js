// Dropping (and picking) the shared torus and running with a fixed seed and one thread gives the
// node and strut counts of the native CLI with the same options, and the model is valid.
import fs from 'node:fs';
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { MESHES, SHARED_MISSING } from './support/paths.js';
import { goldenRun } from './support/cli.js';
import { openPage, summary, dropFile, pickFile, expectNoPageErrors } from './support/page.js';

test.skip(Boolean(SHARED_MISSING), SHARED_MISSING);

const torus = path.join(MESHES, 'torus.obj');
let golden;

test.beforeAll(() => {
  golden = goldenRun(torus, { resolution: 8, proposals: 20000, seed: 7 });
  console.log(`golden: zomeify run --proposals 20000 --threads 1 --seed 7: ${golden.balls} balls, ${golden.struts} struts`);
});

for (const [how, put] of [['drag and drop', dropFile], ['file picker', pickFile]]) {
  test(`torus by ${how}: same counts as the CLI (seed 7, 1 thread)`, async ({ page }) => {
    const { errors } = await openPage(page);
    await page.evaluate((o) => window.zomeify.setOptions(o), golden.options);
    const runsBefore = await page.evaluate(() => window.zomeify.runs());
    await put(page, 'torus.obj', fs.readFileSync(torus)); // "run after loading" is ticked
    await page.waitForFunction((n) => window.zomeify.runs() > n && window.zomeify.state() === 'idle', runsBefore,
      { timeout: 90_000, polling: 50 });
    const s = await summary(page);
    const progress = await page.evaluate(() => window.zomeify.progress());
    expect(progress.state).toBe('done');
    expect(s.source).toBe('run');
    expect({ balls: s.balls, struts: s.struts, faces: s.faces })
      .toEqual({ balls: golden.balls, struts: golden.struts, faces: golden.faces });
    if (golden.options.proposals > 0) {
      // The same run, not only the same size: strut kinds and commits equal; the final energy
      // agrees to 1e-8 relative (bit-identity is for the engine's own tests to pin down).
      expect(s.stats.struts_by_kind).toEqual(golden.stats.struts_by_kind);
      expect(s.stats.commits).toBe(golden.stats.commits);
      const e = golden.stats.energy.end.total;
      expect(Math.abs(s.stats.energy.end.total - e)).toBeLessThan(1e-8 * Math.abs(e));
    }
    expect(s.valid, s.validation).toBe(true);
    expect(s.genus).toBe(1);
    await expectNoPageErrors(errors);
  });
}
