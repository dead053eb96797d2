#!/usr/bin/python3
"""Pictures of models beside their meshes, for the docs (not a test).

usage: picture_models.py OUT.png MESH.obj MODEL.zome.json [TITLE] [--view ELEV,AZIM]

Left the mesh (shaded), right the model in the same view: faces light grey, struts in their Zome
colours (blue, yellow, red by length), at the mesh's scale. Needs Debian's python3-matplotlib.
"""
import json
import math
import random
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

PHI = (1 + 5 ** 0.5) / 2
BASE = [1.0, 3 ** 0.5 / 2, (2 + PHI) ** 0.5 / 2]
LENGTHS = [b * PHI ** k for b in BASE for k in range(3)]  # B0 B1 B2 Y0 Y1 Y2 R0 R1 R2
COLOURS = ["#1f5fbf"] * 3 + ["#e8b400"] * 3 + ["#c8202a"] * 3
MAX_TRIANGLES = 250000


def read_obj(path):
    vs, tris = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vs.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("f "):
                idx = [int(t.split("/")[0]) for t in line.split()[1:]]
                idx = [i - 1 if i > 0 else len(vs) + i for i in idx]
                tris += [(idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1)]
    return vs, tris


def read_model(path):
    m = json.load(open(path))
    t = m.get("transform", {})
    s, tr = t.get("scale", 1.0), t.get("translation", [0, 0, 0])
    zome = [[(n[2 * k] * PHI + n[2 * k + 1]) / 2 for k in range(3)] for n in m["nodes"]]
    nodes = [[s * p[k] + tr[k] for k in range(3)] for p in zome]
    kinds = []
    for a, b in m["struts"]:
        length = math.dist(zome[a], zome[b])
        kinds.append(min(range(9), key=lambda k: abs(length / LENGTHS[k] - 1)))
    return nodes, m["struts"], kinds, m.get("faces", [])


def shade(normal, base):
    light = [0.3, 0.5, 0.8]
    n = math.sqrt(sum(c * c for c in normal)) or 1.0
    d = abs(sum(normal[i] * light[i] for i in range(3))) / n / math.sqrt(sum(c * c for c in light))
    return [min(1.0, c * (0.35 + 0.65 * d)) for c in base]


def face_colours(polys, base):
    return [shade(normal(p), base) for p in polys]


def normal(p):
    u = [p[1][i] - p[0][i] for i in range(3)]
    v = [p[2][i] - p[0][i] for i in range(3)]
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def towards_viewer(view):
    e, a = math.radians(view[0]), math.radians(view[1])
    return [math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)]


def front(polys, eye):
    # (x, z, y) swaps handedness, so a face counter-clockwise from outside faces the viewer when its
    # normal in plot coordinates points away from the eye vector.
    return [p for p in polys if sum(n * e for n, e in zip(normal(p), eye)) < 0]


def axes_like(ax, lo, hi, view):
    c = [(lo[i] + hi[i]) / 2 for i in range(3)]
    r = max(hi[i] - lo[i] for i in range(3)) / 2
    # y is up in the meshes: matplotlib's z axis shows mesh y.
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[2] - r, c[2] + r)
    ax.set_zlim(c[1] - r, c[1] + r)
    ax.set_box_aspect((1, 1, 1), zoom=1.2)
    ax.view_init(*view)
    ax.set_axis_off()


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--view")]
    view = (15, -60)
    for a in sys.argv[1:]:
        if a.startswith("--view"):
            view = tuple(float(x) for x in a.split("=", 1)[1].split(","))
    out, mesh_path, model_path = args[:3]
    title = args[3] if len(args) > 3 else ""
    vs, tris = read_obj(mesh_path)
    random.seed(1)
    if len(tris) > MAX_TRIANGLES:
        tris = random.sample(tris, MAX_TRIANGLES)
    swap = lambda p: (p[0], p[2], p[1])  # noqa: E731
    lo = [min(v[i] for v in vs) for i in range(3)]
    hi = [max(v[i] for v in vs) for i in range(3)]
    nodes, struts, kinds, faces = read_model(model_path)

    fig = plt.figure(figsize=(8, 4), dpi=80)
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    eye = towards_viewer(view)
    polys = front([[swap(vs[i]) for i in t] for t in tris], eye)
    ax.add_collection3d(Poly3DCollection(polys, facecolors=face_colours(polys, [0.8, 0.8, 0.78]), linewidths=0))
    axes_like(ax, lo, hi, view)
    ax.set_title("mesh", fontsize=10)

    ax = fig.add_subplot(1, 2, 2, projection="3d")
    seen = set()
    fpolys = []
    for f in faces:
        p = [swap(nodes[i]) for i in f]
        if front([p], eye):
            fpolys.append(p)
            seen.update((min(f[k], f[k - 1]), max(f[k], f[k - 1])) for k in range(len(f)))
    ax.add_collection3d(Poly3DCollection(fpolys, facecolors=face_colours(fpolys, [0.93, 0.93, 0.91]), linewidths=0))
    shown = [(a, b, k) for (a, b), k in zip(struts, kinds) if (min(a, b), max(a, b)) in seen]
    segs = [(swap(nodes[a]), swap(nodes[b])) for a, b, _ in shown]
    ax.add_collection3d(Line3DCollection(segs, colors=[COLOURS[k] for _, _, k in shown], linewidths=1.3))
    axes_like(ax, lo, hi, view)
    ax.set_title("model", fontsize=10)
    if title:
        fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    fig.savefig(out)


if __name__ == "__main__":
    main()
