// zip.js: CRC-32 against the standard check value, and a zip whose headers, sizes, CRCs and names
// read back entry by entry (a reader written from the format, not from the writer).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { crc32, zipStored } from '../src/zip.js';
import { readZipStored } from './helpers/read_zip.mjs';

test('CRC-32 check value', () => {
  assert.equal(crc32(new TextEncoder().encode('123456789')), 0xcbf43926);
  assert.equal(crc32(new Uint8Array()), 0);
});

test('a stored zip of OBJ + MTL reads back byte for byte', () => {
  const obj = new TextEncoder().encode('mtllib torus.mtl\nv 0 0 0\n');
  const mtl = new TextEncoder().encode('newmtl B0\nKd 0 0 1\n');
  const zip = zipStored([{ name: 'torus.obj', bytes: obj }, { name: 'tørus.mtl', bytes: mtl }]);
  const files = readZipStored(zip);
  assert.deepEqual(files.map((f) => f.name), ['torus.obj', 'tørus.mtl']);
  assert.deepEqual([...files[0].bytes], [...obj]);
  assert.deepEqual([...files[1].bytes], [...mtl]);
  assert.throws(() => readZipStored(zip.slice(0, zip.length - 1)), /end of central directory/);
});
