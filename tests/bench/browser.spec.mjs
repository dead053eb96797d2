// Browser benchmark: annealing proposals/s inside Chromium's worker (the page's threaded wasm build,
// cross-origin isolated), bunny Z0 at 8 cells, at 1 and 2 threads. Writes build/bench/browser.json,
// which tests/bench/run.sh adds to results.json as platform "browser".
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { test } from '@playwright/test';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const MESH = path.resolve(ROOT, '..', 'shared', 'data', 'meshes', 'bunny.obj');
const SECONDS = Number(process.env.BENCH_BROWSER_SECONDS || 5);

test('annealing proposals per second in the browser', async ({ page }) => {
  await page.goto('/');
  const info = await page.evaluate(async () => window.zomeify.ready);
  await page.evaluate(async (bytes) => {
    await window.zomeify.load({ name: 'bunny.obj', bytes: new Uint8Array(bytes) });
  }, [...fs.readFileSync(MESH)]);
  const runs = [];
  for (const threads of [1, 2]) {
    const progress = await page.evaluate(
      (o) => window.zomeify.run({ resolution: 8, seconds: o.seconds, proposals: 0, seed: 1, threads: o.threads }),
      { seconds: SECONDS, threads });
    const p = progress.progress ?? progress;
    runs.push({ threads: p.threads ?? threads, seconds: p.seconds, proposals: p.proposals, commits: p.commits,
      proposals_per_second: p.seconds > 0 ? p.proposals / p.seconds : 0,
      commits_per_second: p.seconds > 0 ? p.commits / p.seconds : 0, energy: p.energy, state: p.state });
    await page.waitForFunction(() => window.zomeify.state() === 'idle', null, { timeout: 60_000, polling: 50 });
  }
  const out = { bench: 'anneal_browser', platform: 'browser', mesh: 'bunny.obj', resolution: 8,
    user_agent: await page.evaluate(() => navigator.userAgent), page: info, runs };
  fs.mkdirSync(path.join(ROOT, 'build', 'bench'), { recursive: true });
  fs.writeFileSync(path.join(ROOT, 'build', 'bench', 'browser.json'), JSON.stringify(out) + '\n');
  console.log(JSON.stringify(out));
});
