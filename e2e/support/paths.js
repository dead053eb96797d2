// Where the tests find the project, the native CLI and the shared meshes.
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const CLI = process.env.ZOMEIFY_CLI || path.join(ROOT, 'build', 'native', 'core', 'cli', 'zomeify');
export const MESHES = path.resolve(ROOT, '..', 'shared', 'data', 'meshes');
export const OUT = path.join(ROOT, 'build', 'e2e-results');
