#!/usr/bin/env bash
# Runs every benchmark natively and as wasm under node; prints one JSON object per line and writes
# them to build/bench/results.jsonl. Builds what is missing first.
set -euo pipefail
cd "$(dirname "$0")/../.."
[ -d build/native ] || bash tests/build.sh native
[ -d build/wasm ] || bash tests/build.sh wasm
mkdir -p build/bench
out=build/bench/results.jsonl; : > "$out"
for exe in build/native/tests/bench/bench_*; do
  [ -x "$exe" ] && [ ! -d "$exe" ] || continue
  "$exe" | tee -a "$out"
done
for js in build/wasm/tests/bench/bench_*.js; do
  [ -f "$js" ] || continue
  case "$js" in *.worker.js) continue ;; esac
  node --no-experimental-fetch "$js" | tee -a "$out"
done
echo "bench: results in $out" >&2
