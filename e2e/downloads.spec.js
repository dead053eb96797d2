// Each download parses back: VEF and JSON through the native CLI, CSV, GLB and OBJ in JS. OBJ and
// its MTL arrive as one .zip (one download, so the browser never asks to allow several). The GLB
// passes the Khronos validator; "VEF, no panels" has the struts and no faces.
import fs from 'node:fs';
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { OUT } from './support/paths.js';
import { partsOf } from './support/cli.js';
import { openPage } from './support/page.js';
import { readZipStored } from '../web/tests/helpers/read_zip.mjs';
import validator from 'gltf-validator';

// The face count of a VEF text (header, vertices W X Y Z, edges, then faces).
function vefFaceCount(text) {
  const t = text.trim().split(/\s+/);
  let i = 5; // vZome VEF 6 field golden
  const vertices = Number(t[i++]);
  i += 4 * vertices;
  const edges = Number(t[i++]);
  i += 2 * edges;
  return Number(t[i]);
}

async function download(page, format) {
  const files = [];
  const count = 1;
  const done = new Promise((resolve) => {
    page.on('download', async function onDownload(d) {
      const file = path.join(OUT, 'downloads', d.suggestedFilename());
      await d.saveAs(file);
      files.push(file);
      if (files.length === count) {
        page.off('download', onDownload);
        resolve();
      }
    });
  });
  await page.click(`[data-format=${format}]`);
  await done;
  return files;
}

test('VEF, GLB, OBJ, JSON and CSV downloads parse back', async ({ page }) => {
  fs.mkdirSync(path.join(OUT, 'downloads'), { recursive: true });
  await openPage(page);
  const parts = await page.evaluate(() => window.zomeify.parts());

  const vefFaces = {};
  for (const format of ['vef', 'vef-struts', 'json']) {
    const [file] = await download(page, format);
    const back = partsOf(file);
    expect(back.balls, format).toBe(parts.balls);
    expect(back.struts, format).toEqual(parts.struts);
    if (format !== 'json') vefFaces[format] = vefFaceCount(fs.readFileSync(file, 'utf8'));
  }
  expect(vefFaces.vef).toBeGreaterThan(0);
  expect(vefFaces['vef-struts']).toBe(0);

  const [csv] = await download(page, 'csv');
  const rows = fs.readFileSync(csv, 'utf8').trim().split('\n').slice(1).map((l) => l.split(','));
  const csvCount = Object.fromEntries(rows.map((r) => [r[1], Number(r[r.length - 1])]));
  expect(csvCount.ball).toBe(parts.balls);
  for (const [kind, n] of Object.entries(parts.struts)) expect(csvCount[kind] ?? 0, kind).toBe(n);

  const [glb] = await download(page, 'glb');
  const bytes = fs.readFileSync(glb);
  expect(bytes.toString('ascii', 0, 4)).toBe('glTF');
  expect(bytes.readUInt32LE(8)).toBe(bytes.length);
  const jsonLength = bytes.readUInt32LE(12);
  const gltf = JSON.parse(bytes.toString('utf8', 20, 20 + jsonLength));
  const strutsTotal = Object.values(parts.struts).reduce((a, b) => a + b, 0);
  expect(gltf.nodes.length).toBeGreaterThanOrEqual(parts.balls + strutsTotal);
  const report = await validator.validateBytes(new Uint8Array(bytes));
  expect([report.issues.numErrors, report.issues.numWarnings]).toEqual([0, 0]);
  expect(gltf.nodes[1].name).toMatch(/^PZB-BAL-W ball \d+$/);

  const [zip] = await download(page, 'obj');
  expect(path.basename(zip)).toMatch(/\.zip$/);
  const entries = readZipStored(new Uint8Array(fs.readFileSync(zip)));
  expect(entries.map((e) => path.extname(e.name)).sort()).toEqual(['.mtl', '.obj']);
  const text = (ext) => new TextDecoder().decode(entries.find((e) => e.name.endsWith(ext)).bytes);
  const obj = text('.obj');
  const mtl = text('.mtl');
  expect(obj).toContain(`mtllib ${entries.find((e) => e.name.endsWith('.mtl')).name}`);
  expect(obj).toMatch(/^mtllib /m);
  const vertices = (obj.match(/^v /gm) || []).length;
  const faces = obj.match(/^f .*/gm) || [];
  expect(faces.length).toBeGreaterThan(0);
  for (const f of faces.slice(0, 2000)) {
    for (const corner of f.slice(2).trim().split(/\s+/)) {
      const i = Number(corner.split('/')[0]);
      expect(i >= 1 && i <= vertices).toBe(true);
    }
  }
  for (const used of new Set((obj.match(/^usemtl (\S+)/gm) || []).map((l) => l.slice(7)))) {
    expect(mtl).toContain(`newmtl ${used}`);
  }
});
