// A reader of stored (uncompressed) zips for the tests (JS unit tests and e2e): finds the end
// record, walks the central directory, checks each local header against it and each entry's CRC-32
// (its own bitwise CRC, independent of the writer's table). Throws on anything else.
function crc32(bytes) {
  let c = 0xffffffff;
  for (const b of bytes) {
    c ^= b;
    for (let k = 0; k < 8; k++) c = (c >>> 1) ^ (0xedb88320 & -(c & 1));
  }
  return (c ^ 0xffffffff) >>> 0;
}

export function readZipStored(zip) {
  const view = new DataView(zip.buffer, zip.byteOffset, zip.byteLength);
  const end = zip.length - 22;
  if (end < 0 || view.getUint32(end, true) !== 0x06054b50) throw new Error('no end of central directory record');
  const count = view.getUint16(end + 10, true);
  let at = view.getUint32(end + 16, true);
  const decoder = new TextDecoder();
  const files = [];
  for (let i = 0; i < count; i++) {
    if (view.getUint32(at, true) !== 0x02014b50) throw new Error(`central entry ${i}: bad signature`);
    if (view.getUint16(at + 10, true) !== 0) throw new Error(`central entry ${i}: compressed`);
    const crc = view.getUint32(at + 16, true), size = view.getUint32(at + 20, true);
    const nameLength = view.getUint16(at + 28, true), extra = view.getUint16(at + 30, true);
    const comment = view.getUint16(at + 32, true), offset = view.getUint32(at + 42, true);
    const name = decoder.decode(zip.subarray(at + 46, at + 46 + nameLength));
    if (view.getUint32(offset, true) !== 0x04034b50) throw new Error(`${name}: bad local header`);
    const localName = view.getUint16(offset + 26, true), localExtra = view.getUint16(offset + 28, true);
    const start = offset + 30 + localName + localExtra;
    const bytes = zip.subarray(start, start + size);
    if (view.getUint32(offset + 14, true) !== crc || crc32(bytes) !== crc) throw new Error(`${name}: CRC mismatch`);
    files.push({ name, bytes });
    at += 46 + nameLength + extra + comment;
  }
  return files;
}
