// The native CLI as the golden reference: the page must give what `zomeify` gives.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { CLI, MESHES, OUT } from './paths.js';

export function cli(args) {
  return execFileSync(CLI, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

/**
 * Runs `zomeify run MESH` with the page's deterministic options and returns the counts.
 * @returns {{balls: number, struts: number, faces: number, options: object, stats: object}}
 */
export function goldenRun(mesh, { resolution, proposals, seed }) {
  fs.mkdirSync(OUT, { recursive: true });
  const out = path.join(OUT, `golden-${path.basename(mesh)}-${resolution}-${proposals}-${seed}.zome.json`);
  // A CLI that cannot anneal (an old build/native without --proposals) throws here: the test fails
  // rather than quietly comparing the initial model only.
  const annealing = proposals > 0;
  const args = ['run', mesh, '-o', out, '--resolution', String(resolution), '--threads', '1', '--seed', String(seed)];
  // The page's runs keep within the kits named before them; the CLI does so with --within-estimate.
  if (annealing) args.push('--proposals', String(proposals), '--within-estimate');
  else args.push('--initial-only');
  cli(args);
  const model = JSON.parse(fs.readFileSync(out, 'utf8'));
  const options = { resolution, threads: 1, seed, proposals: annealing ? proposals : 0, initial_only: !annealing };
  return { balls: model.nodes.length, struts: model.struts.length, faces: (model.faces || []).length, options,
    stats: model.stats || {} };
}

/** `zomeify parts FILE --json` of a downloaded model. */
export function partsOf(file) {
  return JSON.parse(cli(['parts', file, '--json']));
}
