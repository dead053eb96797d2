#!/usr/bin/env python3
"""Writes the generated seed corpora of the fuzz targets: small meshes and pieces of the shared meshes in
every input format, the shared VEF files, and .zome.json files and share links made by the CLI.

    make_seeds.py SHARED_DIR OUT_DIR [ZOMEIFY_CLI ...]

OUT_DIR/<target>/ receives the seeds of each target. The committed, hand-made seeds (bad input, edge
cases) live in tests/fuzz/seeds/ and are passed to libFuzzer beside these. Only the standard library."""
import base64
import json
import os
import struct
import subprocess
import sys
import tempfile

# Pieces of the large meshes: the first faces only, so every seed stays a few KB to a few tens of KB
# (libFuzzer mutates small inputs far more effectively).
PIECE_FACES = (24, 200)
WHOLE_MESHES = ("cube", "sphere")
CUT_MESHES = ("torus", "eight", "bunny", "fertility")


def read_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                vertices.append(tuple(float(x) for x in parts[1:4]))
            elif parts[0] == "f":
                faces.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
    return vertices, faces


def piece(vertices, faces, count):
    """The first `count` faces with only the vertices they use, renumbered."""
    faces = faces[:count]
    used = sorted({i for face in faces for i in face})
    new_index = {old: new for new, old in enumerate(used)}
    return [vertices[i] for i in used], [[new_index[i] for i in face] for face in faces]


def triangles(faces):
    return [(f[0], f[k], f[k + 1]) for f in faces for k in range(1, len(f) - 1)]


def obj_text(v, f):
    return "".join("v %r %r %r\n" % p for p in v) + "".join("f " + " ".join(str(i + 1) for i in face) + "\n" for face in f)


def off_text(v, f):
    return ("OFF\n%d %d 0\n" % (len(v), len(f)) + "".join("%r %r %r\n" % p for p in v) +
            "".join("%d %s\n" % (len(face), " ".join(map(str, face))) for face in f))


def stl_ascii(v, f):
    rows = ["solid seed\n"]
    for t in triangles(f):
        rows.append(" facet normal 0 0 0\n  outer loop\n")
        rows += ["   vertex %r %r %r\n" % v[i] for i in t]
        rows.append("  endloop\n endfacet\n")
    return "".join(rows + ["endsolid seed\n"])


def stl_binary(v, f):
    tris = triangles(f)
    out = bytearray(b"seed".ljust(80, b" ") + struct.pack("<I", len(tris)))
    for t in tris:
        out += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *v[i]) for i in t) + b"\0\0"
    return bytes(out)


def ply(v, f, encoding):
    header = ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (encoding, len(v), len(f)))
    if encoding == "ascii":
        body = "".join("%r %r %r\n" % p for p in v) + "".join(
            "%d %s\n" % (len(face), " ".join(map(str, face))) for face in f)
        return (header + body).encode()
    e = "<" if encoding == "binary_little_endian" else ">"
    body = b"".join(struct.pack(e + "3f", *p) for p in v)
    body += b"".join(struct.pack(e + "B%di" % len(face), len(face), *face) for face in f)
    return header.encode() + body


def gltf_parts(v, f, index_type):
    tris = triangles(f)
    fmt = {5125: "I", 5123: "H"}[index_type]
    positions = b"".join(struct.pack("<3f", *p) for p in v)
    indices = b"".join(struct.pack("<3" + fmt, *t) for t in tris)
    indices += b"\0" * (-len(indices) % 4)
    lo = [min(p[a] for p in v) for a in range(3)]
    hi = [max(p[a] for p in v) for a in range(3)]
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "translation": [0.5, 0, 0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
        "buffers": [{"byteLength": len(positions) + len(indices)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(v), "type": "VEC3", "min": lo, "max": hi},
                      {"bufferView": 1, "componentType": index_type, "count": 3 * len(tris), "type": "SCALAR"}],
    }
    return doc, positions + indices


def gltf_embedded(v, f, index_type):
    doc, data = gltf_parts(v, f, index_type)
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    return json.dumps(doc).encode()


def glb(v, f, index_type):
    doc, data = gltf_parts(v, f, index_type)
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    data += b"\0" * (-len(data) % 4)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(data), 0x004E4942) + data
    return struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks


def write(out_dir, target, name, data):
    os.makedirs(os.path.join(out_dir, target), exist_ok=True)
    with open(os.path.join(out_dir, target, name), "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


def mesh_seeds(shared, out):
    meshes = []
    for name in WHOLE_MESHES:
        meshes.append((name, read_obj(os.path.join(shared, "data/meshes", name + ".obj"))))
    for name in CUT_MESHES:
        v, f = read_obj(os.path.join(shared, "data/meshes", name + ".obj"))
        for count in PIECE_FACES:
            meshes.append(("%s-%d" % (name, count), piece(v, f, count)))
    for name, (v, f) in meshes:
        write(out, "obj", name + ".obj", obj_text(v, f))
        write(out, "off", name + ".off", off_text(v, f))
        write(out, "stl", name + "-ascii.stl", stl_ascii(v, f))
        write(out, "stl", name + "-binary.stl", stl_binary(v, f))
        for encoding in ("ascii", "binary_little_endian", "binary_big_endian"):
            write(out, "ply", "%s-%s.ply" % (name, encoding), ply(v, f, encoding))
        index_type = 5123 if len(v) < 65536 else 5125
        write(out, "gltf", name + ".gltf", gltf_embedded(v, f, index_type))
        write(out, "glb", name + ".glb", glb(v, f, index_type))
    return len(meshes)


def model_seeds(shared, out, cli):
    models = [os.path.join(shared, "data/vef", n) for n in sorted(os.listdir(os.path.join(shared, "data/vef")))
              if n.endswith(".vef")]
    for path in models:
        with open(path, "rb") as f:
            write(out, "vef", os.path.basename(path), f.read())
    if not cli:
        print("make_seeds: no CLI given, so no .zome.json or share-link seeds", file=sys.stderr)
        return
    with tempfile.TemporaryDirectory() as tmp:
        for path in models:
            stem = os.path.basename(path)[:-4]
            json_path = os.path.join(tmp, stem + ".zome.json")
            subprocess.run(cli + ["convert", path, "-o", json_path], check=True, stdout=subprocess.DEVNULL)
            with open(json_path, "rb") as f:
                write(out, "zome_json", stem + ".zome.json", f.read())
            link = subprocess.run(cli + ["link", path], check=True, capture_output=True).stdout.strip()
            write(out, "share_link", stem + ".link", link)
            write(out, "share_link", stem + "-url.link", b"https://example.org/zomeify/#view=3&" + link)


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: make_seeds.py SHARED_DIR OUT_DIR [ZOMEIFY_CLI ...]")
    shared, out, cli = sys.argv[1], sys.argv[2], sys.argv[3:]
    count = mesh_seeds(shared, out)
    model_seeds(shared, out, cli)
    print("make_seeds: %d meshes in 9 formats, VEF, .zome.json and share-link seeds in %s" % (count, out))


if __name__ == "__main__":
    main()
