#!/usr/bin/env bash
# Measures the kit estimate against the kit plan (issue 38): for each shared mesh, with nothing set,
# Z0 at the automatic resolution (`run --initial-only`, the model the page's estimate is made from)
# and a default 30 s run; writes both parts reports (`zomeify parts --json`) and the runs' stats to
# build/bench/kit_estimate/, then prints the table (kit_estimate.py). Native CLI; about 6 minutes.
#   bash tests/bench/kit_estimate.sh [SECONDS]        (SECONDS: the run's budget, default 30)
set -euo pipefail
cd "$(dirname "$0")/../.."
cli=${ZOMEIFY_CLI:-build/native/core/cli/zomeify}
meshes=${ZOMEIFY_SHARED:-../shared}/data/meshes
seconds=${1:-30}
out=build/bench/kit_estimate; mkdir -p "$out"
for mesh in "$meshes"/*.obj; do
  name=$(basename "$mesh" .obj)
  "$cli" run "$mesh" --initial-only -o "$out/$name.z0.zome.json" --stats "$out/$name.z0.json" >/dev/null
  "$cli" run "$mesh" --seconds "$seconds" -o "$out/$name.zome.json" --stats "$out/$name.json" >/dev/null
  "$cli" parts "$out/$name.z0.zome.json" --json > "$out/$name.z0.parts.json"
  "$cli" parts "$out/$name.zome.json" --json > "$out/$name.parts.json"
  echo "kit_estimate: $name done" >&2
done
python3 tests/bench/kit_estimate.py "$out"
