#!/usr/bin/env bash
# Measures the kits named before a run against the kit plan after it (issue 38): for each shared
# mesh, with nothing else set, `run --within-estimate` (as the page: a short pass from Z0 names the
# kits, the run keeps within them) on one thread with a proposal budget (what the page's default
# 30 s gives: about 6·10^6) and seeds 1 and 2; writes the runs' stats and parts reports
# (`zomeify parts --json`) to build/bench/kit_estimate/, then prints the table (kit_estimate.py).
# Native CLI; about 8 minutes.
#   bash tests/bench/kit_estimate.sh [PROPOSALS]        (default 6000000)
set -euo pipefail
cd "$(dirname "$0")/../.."
cli=${ZOMEIFY_CLI:-build/native/core/cli/zomeify}
meshes=${ZOMEIFY_SHARED:-../shared}/data/meshes
proposals=${1:-6000000}
out=build/bench/kit_estimate; mkdir -p "$out"
for mesh in "$meshes"/*.obj; do
  name=$(basename "$mesh" .obj)
  for seed in 1 2; do
    "$cli" run "$mesh" --within-estimate --threads 1 --proposals "$proposals" --seed "$seed" \
      -o "$out/$name.$seed.zome.json" --stats "$out/$name.$seed.json" >/dev/null
    "$cli" parts "$out/$name.$seed.zome.json" --json > "$out/$name.$seed.parts.json"
  done
  echo "kit_estimate: $name done" >&2
done
python3 tests/bench/kit_estimate.py "$out"
