#!/usr/bin/env bash
# The planner against the breadth-first order (issue 24): a markdown table over the ten shared
# meshes' models and the paper's bunny.vef. Models: `zomeify run MESH --resolution 8` annealed for a
# fixed proposal budget on one thread (repeatable), so they hold triangles as real results do.
# Usage: plan_table.sh [ZOMEIFY] [PROPOSALS]   (defaults: build/native/core/cli/zomeify, 20000)
set -euo pipefail
cd "$(dirname "$0")/../.."
cli=${1:-build/native/core/cli/zomeify}
proposals=${2:-20000}
shared=../shared/data
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
row() { # NAME MODEL
  "$cli" steps "$2" --json 2>/dev/null | node -e '
    const p = JSON.parse(require("fs").readFileSync(0, "utf8"));
    const parts = p.steps.reduce((n, s) => n + s.balls.length + s.struts.length, 0);
    const f = p.figures, b = p.naive, pct = (x) => (100 * x).toFixed(0) + "%";
    console.log(`| ${process.argv[1]} | ${p.nodes.length} | ${parts - p.nodes.length} | ${f.steps} / ${b.steps} | ` +
      `${f.max_overhang_mm.toFixed(0)} / ${b.max_overhang_mm.toFixed(0)} | ${pct(f.two_strut_share)} / ${pct(b.two_strut_share)} | ${f.max_dangling} / ${b.max_dangling} |`);' "$1"
}
echo "| model | balls | struts | steps (planner / BFS) | largest overhang mm | steps ending with every new ball on 2 struts | most balls on one strut at once |"
echo "|---|---|---|---|---|---|---|"
for mesh in 3holes bunny cube eight elk fertility rockerarm scorpion sphere torus; do
  [ -f "$shared/meshes/$mesh.obj" ] || { echo "| $mesh | (no mesh) |"; continue; }
  "$cli" run "$shared/meshes/$mesh.obj" --resolution 8 --proposals "$proposals" --threads 1 --seed 1 \
    -o "$tmp/$mesh.zome.json" >/dev/null 2>&1 || { echo "| $mesh | (run failed) |"; continue; }
  row "$mesh" "$tmp/$mesh.zome.json"
done
[ -f "$shared/vef/bunny.vef" ] && row "bunny.vef (paper)" "$shared/vef/bunny.vef"
