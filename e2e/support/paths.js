// Where the tests find the project, the native CLI and the shared meshes.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const CLI = process.env.ZOMEIFY_CLI || path.join(ROOT, 'build', 'native', 'core', 'cli', 'zomeify');
// The shared data folder: $ZOMEIFY_SHARED, else ../shared beside the project (a user's clone has none).
export const SHARED = process.env.ZOMEIFY_SHARED || path.resolve(ROOT, '..', 'shared');
export const MESHES = path.join(SHARED, 'data', 'meshes');
/** Why a spec that reads the shared meshes is skipped, or '' when they are there. */
export const SHARED_MISSING = fs.existsSync(MESHES) ? ''
  : `needs the shared meshes in ${MESHES}, which are absent (set ZOMEIFY_SHARED to the folder that holds data/)`;
export const OUT = path.join(ROOT, 'build', 'e2e-results');
