// Reads a .zome.json model (design.md §4) straight into a viewer Snapshot, without the core, so the
// first sample is on screen before the wasm module has even compiled. Kinds come from strut
// lengths: the nine Zome lengths differ by at least 5 %, so a 1 % match is unambiguous.
// Bad input throws one clear Error before anything is drawn (the caller keeps the current model).
const PHI = (1 + Math.sqrt(5)) / 2;
const BASE = [1, Math.sqrt(3) / 2, Math.sqrt(2 + PHI) / 2]; // b0, y0, r0 (b0 = 1)
/** Centre-to-centre lengths in Zome units, in KIND_NAMES order: B0 B1 B2 Y0 Y1 Y2 R0 R1 R2. */
export const ZOME_LENGTHS = Object.freeze(BASE.flatMap((l) => [l, l * PHI, l * PHI * PHI]));

/** The kind (0..8) of a strut of this length in Zome units, or 255 when it is no Zome length. */
export function kindOfLength(length) {
  for (let k = 0; k < ZOME_LENGTHS.length; k++) if (Math.abs(length / ZOME_LENGTHS[k] - 1) < 0.01) return k;
  return 255;
}

const isIndex = (i, count) => Number.isInteger(i) && i >= 0 && i < count;

/** @returns {import('./protocol.js').Snapshot} */
export function snapshotFromZomeJson(text) {
  let model;
  try {
    model = JSON.parse(text);
  } catch (e) {
    throw new Error(`not a zomeify model (${e.message})`);
  }
  if (model?.format !== 'zomeify-model' || !Array.isArray(model.nodes) || !Array.isArray(model.struts)) {
    throw new Error('not a zomeify model');
  }
  // Checked here, because a bad index would otherwise become NaN positions drawn as garbage.
  const count = model.nodes.length;
  model.nodes.forEach((n, i) => {
    if (!Array.isArray(n) || n.length !== 6 || !n.every(Number.isFinite)) throw new Error(`node ${i} is not 6 numbers`);
  });
  model.struts.forEach((s, i) => {
    if (!Array.isArray(s) || s.length !== 2 || !s.every((v) => isIndex(v, count))) {
      throw new Error(`strut ${i} refers to a missing node`);
    }
  });
  const faces = model.faces || [];
  faces.forEach((f, i) => {
    if (!Array.isArray(f) || !f.every((v) => isIndex(v, count))) throw new Error(`face ${i} refers to a missing node`);
  });
  const positions = new Float32Array(3 * count);
  model.nodes.forEach((n, i) => {
    for (let k = 0; k < 3; k++) positions[3 * i + k] = (n[2 * k] * PHI + n[2 * k + 1]) / 2;
  });
  const struts = new Uint32Array(model.struts.flat());
  const kinds = new Uint8Array(model.struts.length);
  model.struts.forEach(([a, b], i) => {
    const d = [0, 1, 2].map((k) => positions[3 * b + k] - positions[3 * a + k]);
    kinds[i] = kindOfLength(Math.hypot(...d));
  });
  const triangles = [];
  for (const f of faces) for (let i = 1; i + 1 < f.length; i++) triangles.push(f[0], f[i], f[i + 1]);
  const t = model.transform || {};
  return {
    version: -1, positions, struts, kinds, triangles: new Uint32Array(triangles),
    scale: t.scale ?? 1, translation: t.translation ?? [0, 0, 0],
  };
}
