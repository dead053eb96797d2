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
annealing=yes
"$cli" run --help 2>&1 | grep -q -- '--proposals' || annealing=no
for entry in torus:8 sphere:6 cube:5 scorpion:12; do
  id=${entry%%:*}; resolution=${entry##*:}
  out=$dir/$id.zome.json
  if [ -f "$out" ] && [ "$out" -nt "$cli" ] && [ "$out" -nt "$dir/$id.obj" ]; then continue; fi
  if [ $annealing = yes ]; then
    "$cli" run "$dir/$id.obj" -o "$out" --resolution "$resolution" --proposals "$proposals" --threads 1 --seed 1 >/dev/null
  else
    "$cli" run "$dir/$id.obj" -o "$out" --resolution "$resolution" --initial-only >/dev/null
  fi
  echo "sample: $out ($(grep -o '"struts"' "$out" >/dev/null && node -e "const m=require('./$out');console.log(m.nodes.length+' balls, '+m.struts.length+' struts')"))"
done
