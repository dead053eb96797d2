// The GLB exports against the tools people open them with (issue 25): the Khronos glTF validator
// (npm gltf-validator) must report 0 errors and 0 warnings for every GLB written here, and
// three.js's GLTFLoader must load one under node with a bounding box, in metres, equal to the
// built size `zomeify parts --json` reports (within 1%), centred in x and z and resting on y = 0.
// Usage: node tests/io/gltf_check.mjs ZOMEIFY SHARED_DATA_DIR   (ctest: gltf_native)
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import validator from 'gltf-validator';
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

const [zomeify, sharedArg] = process.argv.slice(2);
const shared = process.env.ZOMEIFY_SHARED || sharedArg;
if (!fs.existsSync(path.join(shared, 'data'))) {
  // A user's clone without ../shared: skipped (ctest SKIP_RETURN_CODE), not failed.
  console.log(`skipped: the GLB checks read models from ${path.join(shared, 'data')}, which is absent (set ZOMEIFY_SHARED)`);
  process.exit(77);
}
const here = path.dirname(fileURLToPath(import.meta.url));
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'zomeify-gltf-'));
const models = {
  bunny: path.join(shared, 'data/vef/bunny.vef'),
  icosahedron: path.join(here, '../data/samples/icosahedron.zome.json'),
  vzome10: path.join(here, '../data/vef/vzome10_copy.vef'),
  dome: path.join(shared, 'data/vef/dome.vef'),
};
let failures = 0;
const fail = (what) => {
  failures++;
  console.log(`FAIL ${what}`);
};

async function loadGlb(bytes) {
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
}

for (const [name, model] of Object.entries(models)) {
  const glb = path.join(tmp, `${name}.glb`);
  execFileSync(zomeify, ['convert', model, '-o', glb], { stdio: ['ignore', 'ignore', 'ignore'] });
  const bytes = new Uint8Array(fs.readFileSync(glb));
  const report = await validator.validateBytes(bytes);
  const { numErrors, numWarnings, numInfos } = report.issues;
  console.log(`${name}.glb: validator ${report.validatorVersion}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos`);
  if (numErrors || numWarnings) {
    fail(`${name}.glb: ${JSON.stringify(report.issues.messages.slice(0, 5))}`);
    continue;
  }

  const gltf = await loadGlb(bytes);
  const box = new THREE.Box3().setFromObject(gltf.scene);
  const size = box.getSize(new THREE.Vector3());
  const parts = JSON.parse(execFileSync(zomeify, ['parts', model, '--json'], { stdio: ['ignore', 'pipe', 'ignore'] }));
  const built = parts.size_cm.map((cm) => cm / 100);
  const got = [size.x, size.y, size.z];
  const worst = Math.max(...got.map((g, k) => Math.abs(g - built[k]) / built[k]));
  console.log(`${name}.glb: GLTFLoader box ${got.map((x) => x.toFixed(4)).join(' x ')} m, parts ${built
    .map((x) => x.toFixed(4)).join(' x ')} m, worst ${(100 * worst).toFixed(3)}%; min y ${box.min.y.toFixed(6)}`);
  if (!(worst <= 0.01)) fail(`${name}.glb: box differs from the built size by ${(100 * worst).toFixed(2)}%`);
  if (Math.abs(box.min.y) > 1e-4) fail(`${name}.glb: lowest point at y = ${box.min.y}, not on the table`);
  if (Math.abs(box.min.x + box.max.x) > 1e-4 || Math.abs(box.min.z + box.max.z) > 1e-4)
    fail(`${name}.glb: not centred in x and z`);
}
fs.rmSync(tmp, { recursive: true, force: true });
console.log(failures ? `gltf check: ${failures} failed` : 'gltf check: all passed');
process.exit(failures ? 1 : 0);
