#!/usr/bin/env python3
"""The default-size experiment of issue 37 (core/voxel/README.md, "Automatic resolution").

For each mesh and each (preferred grid P, target ratio F, cap C): the grid the automatic rule takes
for P (P, else the nearest grid that keeps the genus, finer first: `run --initial-only --resolution R`),
then a short run there asking the annealer for max(Z0, min(F x Z0, C)) balls, then `parts` (built
size, kits) and `score` (symmetric RMS, largest gap). Prints one markdown row per run.

  python3 tests/bench/default_size.py CLI OUT_DIR "8:1.8:400 10:1.8" mesh.obj ...
"""
import json
import os
import subprocess
import sys


def run(cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def z0(cli, mesh, resolution, out):
    stats = os.path.join(out, "z0.json")
    run([cli, "run", mesh, "--initial-only", "--resolution", str(resolution), "-o", os.path.join(out, "z0.zome.json"),
         "--stats", stats])
    s = json.load(open(stats))
    return s["initial"]["N"], s["initial"]["genus"]


def surface_genus(cli, mesh):
    return json.loads(run([cli, "inspect", mesh, "--json"]))["genus"]


def main():
    cli, out, configs, meshes = sys.argv[1], sys.argv[2], sys.argv[3].split(), sys.argv[4:]
    os.makedirs(out, exist_ok=True)
    print("| mesh | P:F:C | grid | Z0 balls | target | balls | built size (cm) | kits | RMS b0 (mm) | largest gap b0 (mm) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for mesh in meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        genus = surface_genus(cli, mesh)
        for config in configs:
            fields = config.split(":")
            p, f = int(fields[0]), float(fields[1])
            cap = int(fields[2]) if len(fields) > 2 else 10**9
            order = [p] + [r for d in range(1, 27) for r in (p + d, p - d) if 6 <= r <= 32]
            grid, balls = None, 0
            for r in order:
                n, g = z0(cli, mesh, r, out)
                if g == genus:
                    grid, balls = r, n
                    break
            if grid is None:
                print(f"| {name} | {config} | none keeps genus {genus} | | | | | | | |")
                continue
            target = max(balls, min(round(f * balls), cap))
            model = os.path.join(out, f"{name}-{p}-{f}.zome.json")
            run([cli, "run", mesh, "--resolution", str(grid), "--target-nodes", str(target), "--threads", "1",
                 "--proposals", "2000000", "--seed", "1", "-o", model, "--stats", os.path.join(out, "s.json")])
            parts = json.loads(run([cli, "parts", model, "--json"]))
            size = max(parts["size_cm"]) if "size_cm" in parts else None
            kits = " + ".join(f"{k['count']} {k['name']}" for k in parts["kit_plan"]["kits"])
            score = json.loads(run([cli, "score", model, "--mesh", mesh, "--json"]))
            fid = score.get("fidelity", score)
            print(f"| {name} | {config} | {grid} | {balls} | {target} | {parts['balls']} | {size:.0f} | {kits} | "
                  f"{fid['rms_symmetric_b0']:.3f} ({fid['rms_symmetric_mm']:.1f}) | "
                  f"{fid['hausdorff_b0']:.2f} ({fid['hausdorff_mm']:.0f}) |", flush=True)


if __name__ == "__main__":
    main()
