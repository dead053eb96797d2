// Browser benchmark (issue 39): the paper's bunny in the real page. For each thread count and seed,
// the page runs the bunny at the paper's size (8 cells, 392 balls) for BENCH_PAPER_SECONDS (30) through
// window.zomeify.run, while the main thread's frames are timed (requestAnimationFrame: is the page
// still responsive?); the model is exported and scored with the native CLI (`score --samples 400000`)
// against the paper's model (symmetric RMS 0.150 b0, Hausdorff 0.646 b0). Then the native CLI runs the
// same work for the same time, so the page's proposals per second are compared with the CLI's in one
// run (alternating, as the host's speed drifts). Writes build/bench/browser_paper.json.
//   npx playwright test -c tests/bench/browser.config.mjs browser_paper
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { test } from '@playwright/test';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const MESH = path.resolve(ROOT, '..', 'shared', 'data', 'meshes', 'bunny.obj');
const CLI = path.join(ROOT, 'build', 'native', 'core', 'cli', 'zomeify');
const SECONDS = Number(process.env.BENCH_PAPER_SECONDS || 30);
const SEEDS = (process.env.BENCH_PAPER_SEEDS || '1 2 3').split(/\s+/).map(Number);
const THREADS = (process.env.BENCH_PAPER_THREADS || '1 2').split(/\s+/).map(Number);
const PAPER = { rms_sym_b0: 0.15, hausdorff_b0: 0.646 };

function score(modelPath) {
  const s = JSON.parse(execFileSync(CLI, ['score', modelPath, '--mesh', MESH, '--samples', '400000', '--json']));
  const r = { rms_sym_b0: s.fidelity.rms_symmetric_b0, hausdorff_b0: s.fidelity.hausdorff_b0,
    clashes: s.clearance.clashes, fold_overs: s.fold_overs, genus: s.genus, balls: s.nodes };
  r.beats_paper = r.rms_sym_b0 <= PAPER.rms_sym_b0 && r.hausdorff_b0 <= PAPER.hausdorff_b0 && r.clashes === 0 &&
    r.fold_overs === 0;
  return r;
}

function nativeRun(threads, seed, dir) {
  const model = path.join(dir, `native-${threads}-${seed}.zome.json`);
  const stats = path.join(dir, `native-${threads}-${seed}.stats.json`);
  const t0 = Date.now();
  execFileSync(CLI, ['run', MESH, '--resolution', '8', '--target-nodes', '392', '--seconds', String(SECONDS),
    '--threads', String(threads), '--seed', String(seed), '-o', model, '--stats', stats], { stdio: 'ignore' });
  const st = JSON.parse(fs.readFileSync(stats, 'utf8'));
  return { wall_seconds: (Date.now() - t0) / 1000, anneal_seconds: st.wall_seconds, proposals: st.proposals,
    proposals_per_second: st.proposals / st.wall_seconds, ...score(model) };
}

// Gaps between the main thread's animation frames, in ms: median, 95th percentile, largest, and how
// many exceeded 50 ms (a frame a person notices as a stutter).
function frameFigures(times) {
  const gaps = times.slice(1).map((t, i) => t - times[i]).sort((a, b) => a - b);
  const at = (q) => (gaps.length ? gaps[Math.min(gaps.length - 1, Math.floor(q * gaps.length))] : 0);
  return { frames: times.length, gap_median_ms: at(0.5), gap_p95_ms: at(0.95), gap_max_ms: gaps.at(-1) ?? 0,
    gaps_over_50ms: gaps.filter((g) => g > 50).length };
}

test('the paper\'s bunny in the page: time to beat it, frame gaps, page against CLI', async ({ page }) => {
  test.setTimeout((SECONDS * 2 + 40) * 1000 * SEEDS.length * THREADS.length + 120_000);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'zome-paper-'));
  await page.goto('/');
  const info = await page.evaluate(async () => window.zomeify.ready);
  await page.evaluate(async () => window.zomeify.warmedUp());
  await page.evaluate(async (bytes) => {
    await window.zomeify.load({ name: 'bunny.obj', bytes: new Uint8Array(bytes) });
  }, [...fs.readFileSync(MESH)]);
  const runs = [];
  for (const seed of SEEDS) {
    for (const threads of THREADS) {
      const t0 = Date.now();
      const r = await page.evaluate(async (o) => {
        const times = [];
        let on = true;
        const tick = (t) => { times.push(t); if (on) requestAnimationFrame(tick); };
        requestAnimationFrame(tick);
        const p = await window.zomeify.run({ resolution: 8, target_nodes: 392, seconds: o.seconds, proposals: 0,
          seed: o.seed, threads: o.threads });
        on = false;
        return { progress: p.progress ?? p, times };
      }, { seconds: SECONDS, threads, seed });
      const wall = (Date.now() - t0) / 1000;
      await page.waitForFunction(() => window.zomeify.state() === 'idle', null, { timeout: 60_000, polling: 50 });
      const file = await page.evaluate(async () => {
        const f = await window.zomeify.exportModel('bunny.zome.json');
        return [...f.bytes];
      });
      const modelPath = path.join(dir, `page-${threads}-${seed}.zome.json`);
      fs.writeFileSync(modelPath, Buffer.from(file));
      const p = r.progress;
      // A timed run anneals for its budget; p.seconds also counts the starting model and the kits'
      // short pass before it.
      const annealSeconds = p.budget_seconds > 0 ? Math.min(p.budget_seconds, p.seconds) : p.seconds;
      const pageRun = { wall_seconds: wall, run_seconds: p.seconds, anneal_seconds: annealSeconds,
        proposals: p.proposals, proposals_per_second: annealSeconds > 0 ? p.proposals / annealSeconds : 0,
        threads_used: p.threads,
        ...frameFigures(r.times), ...score(modelPath) };
      const native = nativeRun(threads, seed, dir);
      const row = { seed, threads, page: pageRun, native,
        page_over_native: native.proposals_per_second > 0 ? pageRun.proposals_per_second / native.proposals_per_second : 0 };
      runs.push(row);
      console.log(JSON.stringify(row));
    }
  }
  const out = { bench: 'anneal_browser_paper', mesh: 'bunny.obj', resolution: 8, target_nodes: 392, seconds: SECONDS,
    paper: PAPER, user_agent: await page.evaluate(() => navigator.userAgent), page: info, runs };
  fs.mkdirSync(path.join(ROOT, 'build', 'bench'), { recursive: true });
  fs.writeFileSync(path.join(ROOT, 'build', 'bench', 'browser_paper.json'), JSON.stringify(out) + '\n');
  fs.rmSync(dir, { recursive: true, force: true });
});
