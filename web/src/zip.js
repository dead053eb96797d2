// A .zip of a few small files, stored without compression (what OBJ + MTL need to arrive as one
// download; every unzip tool and OS reads "stored" entries). Format: PKWARE APPNOTE 4.3.
const CRC_TABLE = (() => {
  const table = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    table[n] = c >>> 0;
  }
  return table;
})();

/** CRC-32 (IEEE) of the bytes, as zip stores it. */
export function crc32(bytes) {
  let c = 0xffffffff;
  for (const b of bytes) c = CRC_TABLE[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

/** @param {{name: string, bytes: Uint8Array}[]} files @returns {Uint8Array} the zip */
export function zipStored(files) {
  const encoder = new TextEncoder();
  const entries = files.map((f) => ({ ...f, nameBytes: encoder.encode(f.name), crc: crc32(f.bytes) }));
  const localSize = entries.reduce((n, e) => n + 30 + e.nameBytes.length + e.bytes.length, 0);
  const centralSize = entries.reduce((n, e) => n + 46 + e.nameBytes.length, 0);
  const out = new Uint8Array(localSize + centralSize + 22);
  const view = new DataView(out.buffer);
  let at = 0;
  const u16 = (v) => { view.setUint16(at, v, true); at += 2; };
  const u32 = (v) => { view.setUint32(at, v, true); at += 4; };
  const bytes = (b) => { out.set(b, at); at += b.length; };
  // DOS date 2026-01-01 00:00: a fixed stamp keeps the download the same for the same model.
  const time = 0, date = ((2026 - 1980) << 9) | (1 << 5) | 1;
  for (const e of entries) {
    e.offset = at;
    u32(0x04034b50); u16(20); u16(0x0800); u16(0); u16(time); u16(date); // UTF-8 names, stored
    u32(e.crc); u32(e.bytes.length); u32(e.bytes.length); u16(e.nameBytes.length); u16(0);
    bytes(e.nameBytes); bytes(e.bytes);
  }
  const central = at;
  for (const e of entries) {
    u32(0x02014b50); u16(20); u16(20); u16(0x0800); u16(0); u16(time); u16(date);
    u32(e.crc); u32(e.bytes.length); u32(e.bytes.length); u16(e.nameBytes.length); u16(0); u16(0); u16(0); u16(0);
    u32(0); u32(e.offset); bytes(e.nameBytes);
  }
  const centralLength = at - central;
  u32(0x06054b50); u16(0); u16(0); u16(entries.length); u16(entries.length);
  u32(centralLength); u32(central); u16(0);
  return out;
}
