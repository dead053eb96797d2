// The native CLI as the golden reference: the page must give what `zomeify` gives.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { CLI, MESHES, OUT } from './paths.js';

export function cli(args) {
  return execFileSync(CLI, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

/** Whether this CLI's `run` anneals with a proposal budget (else only --initial-only works). */
export function cliHasProposals() {
  fs.mkdirSync(OUT, { recursive: true });
  try {
    cli(['run', path.join(MESHES, 'cube.obj'), '--resolution', '4', '--proposals', '1', '--threads', '1',
      '-o', path.join(OUT, 'probe.zome.json')]);
    return true;
  } catch {
    return false;
  }
}

/**
 * Runs `zomeify run MESH` with the page's deterministic options and returns the counts.
 * @returns {{balls: number, struts: number, faces: number, options: object, stats: object}}
 */
export function goldenRun(mesh, { resolution, proposals, seed }) {
  fs.mkdirSync(OUT, { recursive: true });
  const out = path.join(OUT, `golden-${path.basename(mesh)}-${resolution}-${proposals}-${seed}.zome.json`);
  const annealing = proposals > 0 && cliHasProposals();
  const args = ['run', mesh, '-o', out, '--resolution', String(resolution), '--threads', '1', '--seed', String(seed)];
  if (annealing) args.push('--proposals', String(proposals));
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
