#!/usr/bin/env bash
# Precomputes the finished model of every bundled sample with the native CLI, so the page shows
# one at once on first open: web/public/samples/<id>.zome.json (generated, not committed).
# Resolutions match web/src/samples.js. Skips samples that are newer than the CLI and the mesh.
#   bash web/build_samples.sh [CLI]      (default build/native/core/cli/zomeify)
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${1:-build/native/core/cli/zomeify}
dir=web/public/samples
proposals=${ZOME_SAMPLE_PROPOSALS:-400000}
seconds=${ZOME_SAMPLE_SECONDS:-10}
probe=$(mktemp --suffix=.zome.json)
has_proposals=no
"$cli" run "$dir/cube.obj" --resolution 4 --proposals 1 --threads 1 -o "$probe" >/dev/null 2>&1 && has_proposals=yes
rm -f "$probe"
for entry in torus:8 sphere:6 cube:5 scorpion:12; do
  id=${entry%%:*}; resolution=${entry##*:}
  out=$dir/$id.zome.json
  if [ -f "$out" ] && [ "$out" -nt "$cli" ] && [ "$out" -nt "$dir/$id.obj" ]; then continue; fi
  common=("$cli" run "$dir/$id.obj" -o "$out" --resolution "$resolution" --threads 1 --seed 1)
  # A proposal budget makes the sample the same on every machine; older CLIs only have a time
  # budget, or no annealer at all (then the sample is Z0).
  if [ $has_proposals = yes ]; then
    "${common[@]}" --proposals "$proposals" >/dev/null
  elif ! "${common[@]}" --seconds "$seconds" >/dev/null 2>&1; then
    "$cli" run "$dir/$id.obj" -o "$out" --resolution "$resolution" --initial-only >/dev/null
  fi
  echo "sample: $out ($(node -e "const m=require('./$out');console.log(m.nodes.length+' balls, '+m.struts.length+' struts')"))"
done
