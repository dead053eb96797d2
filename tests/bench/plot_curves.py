#!/usr/bin/env python3
"""Draws time-to-quality curves (energy against wall time) from build/bench/results.json as an SVG,
one panel per mesh. Dependency-free: the SVG is written by hand.

    plot_curves.py RESULTS_JSON OUT_SVG

Curves are read from the bench_anneal results: any object with a "mesh" (or "name") and a list of
points under "curve", "points", "energy_vs_time" or "time_to_quality", each point [seconds, energy] or
{"t"|"time_s"|"seconds"|"wall_s": ..., "energy"|"E": ...}. "threads" in the object or its parents
labels the series. Without curves the SVG says so (the script does not fail)."""
import json
import math
import sys

CURVE_KEYS = ("curve", "points", "energy_vs_time", "time_to_quality")
TIME_KEYS = ("t", "time_s", "seconds", "wall_s", "time")
ENERGY_KEYS = ("energy", "E", "e")
MESH_ORDER = ("bunny", "fertility", "rockerarm")
COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf")


def point(p):
    if isinstance(p, (list, tuple)) and len(p) >= 2 and all(isinstance(x, (int, float)) for x in p[:2]):
        return float(p[0]), float(p[1])
    if isinstance(p, dict):
        t = next((p[k] for k in TIME_KEYS if isinstance(p.get(k), (int, float))), None)
        e = next((p[k] for k in ENERGY_KEYS if isinstance(p.get(k), (int, float))), None)
        if t is not None and e is not None:
            return float(t), float(e)
    return None


def find_curves(value, context, out):
    if isinstance(value, dict):
        context = dict(context)
        for k in ("mesh", "name", "threads", "platform"):
            if isinstance(value.get(k), (str, int)):
                context[k] = value[k]
        for key in CURVE_KEYS:
            if isinstance(value.get(key), list):
                pts = [q for q in (point(p) for p in value[key]) if q]
                if len(pts) >= 2 and ("mesh" in context or "name" in context):
                    out.append((context, sorted(pts)))
        for k, v in value.items():
            if k not in CURVE_KEYS:
                find_curves(v, context, out)
    elif isinstance(value, list):
        for v in value:
            find_curves(v, context, out)


def mesh_name(context):
    name = str(context.get("mesh", context.get("name", "?")))
    return name[:-4] if name.endswith(".obj") else name


def nice_ticks(lo, hi, count=5):
    if hi <= lo:
        hi = lo + 1.0
    step = 10 ** math.floor(math.log10((hi - lo) / count))
    for m in (1, 2, 5, 10):
        if (hi - lo) / (step * m) <= count:
            step *= m
            break
    first = math.ceil(lo / step) * step
    return [first + i * step for i in range(int((hi - first) / step) + 1)]


def label(x):
    return ("%.3g" % x) if abs(x) < 1e4 else ("%.2e" % x)


def panel(title, series, x0, y0, w, h):
    """One plot: axes, ticks, a polyline per series, legend. Returns SVG elements."""
    xs = [t for _, pts in series for t, _ in pts]
    ys = [e for _, pts in series for _, e in pts]
    xlo, xhi = 0.0, max(xs) if xs else 1.0
    ylo, yhi = (min(ys), max(ys)) if ys else (0.0, 1.0)
    if yhi <= ylo:
        yhi = ylo + 1.0
    pad = 0.05 * (yhi - ylo)
    ylo, yhi = ylo - pad, yhi + pad
    left, bottom, right, top = x0 + 60, y0 + h - 40, x0 + w - 10, y0 + 30
    sx = lambda t: left + (t - xlo) / (xhi - xlo or 1.0) * (right - left)
    sy = lambda e: bottom - (e - ylo) / (yhi - ylo) * (bottom - top)
    el = ['<text x="%g" y="%g" font-size="14" text-anchor="middle" font-weight="bold">%s</text>' % (
        (left + right) / 2, y0 + 18, title),
          '<rect x="%g" y="%g" width="%g" height="%g" fill="none" stroke="#444"/>' % (left, top, right - left,
                                                                                  bottom - top)]
    for t in nice_ticks(xlo, xhi):
        el.append('<line x1="%g" y1="%g" x2="%g" y2="%g" stroke="#ddd"/>' % (sx(t), top, sx(t), bottom))
        el.append('<text x="%g" y="%g" font-size="10" text-anchor="middle">%s</text>' % (sx(t), bottom + 14, label(t)))
    for e in nice_ticks(ylo, yhi):
        el.append('<line x1="%g" y1="%g" x2="%g" y2="%g" stroke="#ddd"/>' % (left, sy(e), right, sy(e)))
        el.append('<text x="%g" y="%g" font-size="10" text-anchor="end">%s</text>' % (left - 4, sy(e) + 3, label(e)))
    el.append('<text x="%g" y="%g" font-size="11" text-anchor="middle">wall time (s)</text>' % ((left + right) / 2,
                                                                                              bottom + 30))
    el.append('<text x="%g" y="%g" font-size="11" text-anchor="middle" transform="rotate(-90 %g %g)">energy</text>' % (
        x0 + 14, (top + bottom) / 2, x0 + 14, (top + bottom) / 2))
    for i, (name, pts) in enumerate(series):
        colour = COLOURS[i % len(COLOURS)]
        path = " ".join("%.1f,%.1f" % (sx(t), sy(e)) for t, e in pts)
        el.append('<polyline fill="none" stroke="%s" stroke-width="1.5" points="%s"/>' % (colour, path))
        el.append('<text x="%g" y="%g" font-size="10" fill="%s" text-anchor="end">%s</text>' % (
            right - 4, top + 12 + 12 * i, colour, name))
    return el


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        doc = json.load(f)
    curves = []
    for run in doc.get("runs", []):
        if run.get("bench") in ("bench_anneal", "bench_quality"):
            find_curves(run.get("results", []), {"platform": run.get("platform")}, curves)
    by_mesh = {}
    for context, pts in curves:
        name = " ".join(str(context[k]) + (" threads" if k == "threads" else "")
                        for k in ("platform", "threads") if k in context)
        by_mesh.setdefault(mesh_name(context), []).append((name, pts))
    meshes = [m for m in MESH_ORDER if m in by_mesh] + sorted(m for m in by_mesh if m not in MESH_ORDER)
    w, h = 420, 320
    width = max(1, len(meshes)) * w
    el = []
    if not meshes:
        el.append('<text x="20" y="40" font-size="14">No energy-vs-time points: bench_anneal has not reported '
                  'any (not built yet, or it failed).</text>')
        print("plot_curves: no curves in %s" % sys.argv[1], file=sys.stderr)
    for i, m in enumerate(meshes):
        el += panel(m, by_mesh[m], i * w, 0, w, h)
    svg = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif">' % (width, h),
           '<rect width="100%" height="100%" fill="white"/>'] + el + ["</svg>"]
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main()
