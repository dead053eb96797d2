// Writes public/favicon.ico: the icon of public/favicon.svg (a white ball with a blue, a yellow and
// a red strut) drawn pixel by pixel, for browsers that ask for /favicon.ico whatever the page links.
// One 32×32 32-bit image; run once after changing the drawing: node web/make_favicon.mjs
import fs from 'node:fs';

const N = 32;
const STRUTS = [[[5, 6], '3d7bf0'], [[28, 9], 'f2c20f'], [[16, 28], 'e0352b']];
const rgb = (hex) => [0, 2, 4].map((i) => parseInt(hex.slice(i, i + 2), 16));

/** Distance from p to the segment a–b. */
function toSegment([px, py], [ax, ay], [bx, by]) {
  const dx = bx - ax, dy = by - ay;
  const t = Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)));
  return Math.hypot(px - ax - t * dx, py - ay - t * dy);
}

function colour(x, y) {
  const p = [x + 0.5, y + 0.5];
  if (Math.hypot(p[0] - 16, p[1] - 16) <= 5) return [255, 255, 255];
  for (const [end, hex] of STRUTS) if (toSegment(p, [16, 16], end) <= 2) return rgb(hex);
  return rgb('16191e');
}

// ICO header, one directory entry, then a BMP without its file header (height doubled: image + mask).
const pixels = Buffer.alloc(N * N * 4);
for (let y = 0; y < N; y++) {
  for (let x = 0; x < N; x++) {
    const [r, g, b] = colour(x, y);
    pixels.set([b, g, r, 255], ((N - 1 - y) * N + x) * 4); // rows bottom-up, BGRA
  }
}
const mask = Buffer.alloc((N / 8) * N); // all opaque (rows of 4 bytes: 32 bits, already aligned)
const info = Buffer.alloc(40);
info.writeUInt32LE(40, 0); info.writeInt32LE(N, 4); info.writeInt32LE(2 * N, 8);
info.writeUInt16LE(1, 12); info.writeUInt16LE(32, 14); info.writeUInt32LE(pixels.length + mask.length, 20);
const image = Buffer.concat([info, pixels, mask]);
const head = Buffer.alloc(22);
head.writeUInt16LE(0, 0); head.writeUInt16LE(1, 2); head.writeUInt16LE(1, 4);
head.writeUInt8(N, 6); head.writeUInt8(N, 7); head.writeUInt16LE(1, 10); head.writeUInt16LE(32, 12);
head.writeUInt32LE(image.length, 14); head.writeUInt32LE(22, 18);
fs.writeFileSync(new URL('./public/favicon.ico', import.meta.url), Buffer.concat([head, image]));
