#!/usr/bin/env bash
# The benchmark command (`npm run bench`): every benchmark natively and as wasm under node, one at a time.
#   tests/bench/run.sh [--quick] [--native-only]
# Writes build/bench/results.json (every result, the machine, wall time and peak memory of each run),
# build/bench/results.md (the table, with wasm/native ratios) and build/bench/time_to_quality.svg
# (energy against wall time from bench_quality); with Playwright installed (npm ci) also the proposals/s
# inside Chromium's worker (browser.spec.mjs). --quick gives the benchmarks smaller workloads so the
# whole command takes a few minutes; the README's figures come from the full run.
# Builds the benchmark targets first (build/native, build/wasm; BENCH_NATIVE_DIR / BENCH_WASM_DIR override).
set -euo pipefail
cd "$(dirname "$0")/../.."
export NODE_PATH=/usr/share/nodejs
quick=0; wasm=1
for arg in "$@"; do
  case "$arg" in
    --quick) quick=1 ;;
    --native-only) wasm=0 ;;
    *) echo "usage: tests/bench/run.sh [--quick] [--native-only]" >&2; exit 2 ;;
  esac
done
native_dir=${BENCH_NATIVE_DIR:-build/native}
wasm_dir=${BENCH_WASM_DIR:-build/wasm}
out=build/bench; mkdir -p "$out"
# Every bench the CMake file declares, in its order: new benchmarks are picked up without editing this.
mapfile -t benches < <(sed -nE 's/^zome_bench\(([a-z_0-9]+)\).*/\1/p' tests/bench/CMakeLists.txt)

build() { # build DIR CONFIGURE-FLAVOUR
  [ -f "$1/CMakeCache.txt" ] || bash tests/build.sh "$2" >/dev/null
  cmake --build "$1" -j"$(nproc)" --target "${benches[@]}" >/dev/null
}
build "$native_dir" native
[ $wasm = 0 ] || build "$wasm_dir" wasm

# The invocations of a bench, one line of arguments each (an empty line: no arguments). Quick mode
# keeps the same kind of work, only less of it.
invocations() {
  if [ $quick = 1 ]; then
    case "$1" in
      bench_projection) echo fertility.obj ;;
      bench_voxel) echo rockerarm.obj 24 ;;
      bench_energy) echo bunny.obj 200 ;;
      bench_import) echo --runs 1 ;;
      bench_anneal) echo throughput 1 ;;
      bench_quality) echo --seconds 4 ;;
      *) echo ;;
    esac
  else
    case "$1" in
      bench_anneal) echo throughput 5; echo "native: quality 30 300 2"; echo "native: seeding 20000000 3" ;;
      bench_quality) echo --seconds 30 ;;
      *) echo ;;
    esac
  fi
}

jsonl="$out/runs.jsonl"; : > "$jsonl"
run_one() { # run_one PLATFORM BENCH ARGS COMMAND...
  local platform=$1 bench=$2 args=$3; shift 3
  local stdout stats; stdout=$(mktemp); stats=$(mktemp)
  echo "bench: $bench $args ($platform)" >&2
  local rc=0
  /usr/bin/time -v -o "$stats" "$@" >"$stdout" || rc=$?
  python3 tests/bench/collect.py record "$platform" "$bench" "$args" "$rc" "$stdout" "$stats" >>"$jsonl"
  rm -f "$stdout" "$stats"
}
for bench in "${benches[@]}"; do
  while IFS= read -r line; do
    # "native: ARGS": long runs (time to quality, seeding) run natively only; a wasm twin would double the time.
    native_only=0; [[ "$line" == native:* ]] && { native_only=1; line=${line#native: }; }
    read -ra args <<<"$line"
    exe="$native_dir/tests/bench/$bench"
    if [ -x "$exe" ]; then run_one native "$bench" "$line" "$exe" "${args[@]}"; fi
    js="$wasm_dir/tests/bench/$bench.js"
    if [ $wasm = 1 ] && [ $native_only = 0 ] && [ -f "$js" ]; then
      run_one wasm "$bench" "$line" node --no-experimental-fetch "$js" "${args[@]}"
    fi
  done < <(invocations "$bench")
done

# Proposals/s inside Chromium's worker (Playwright, the page's threaded build), when Playwright is
# installed (npm ci) and not --native-only; BENCH_SKIP_BROWSER=1 skips it.
if [ $wasm = 1 ] && [ -d node_modules/@playwright/test ] && [ "${BENCH_SKIP_BROWSER:-0}" != 1 ]; then
  echo "bench: browser (Chromium, Playwright)" >&2
  rm -f "$out/browser.json"; rc=0
  seconds=5; [ $quick = 0 ] || seconds=2
  { bash web/build.sh >/dev/null &&
    BENCH_BROWSER_SECONDS=$seconds npx playwright test -c tests/bench/browser.config.mjs "browser\.spec" >"$out/browser.log" 2>&1; } || rc=$?
  if [ ! -s "$out/browser.json" ] && [ $rc -eq 0 ]; then rc=1; fi
  touch "$out/browser.json"; : > "$out/browser.time"
  python3 tests/bench/collect.py record browser bench_anneal_browser "" "$rc" "$out/browser.json" "$out/browser.time" >>"$jsonl"
fi

mode=full; [ $quick = 0 ] || mode=quick
python3 tests/bench/collect.py report "$jsonl" "$out/results.json" "$out/results.md" "$mode"
python3 tests/bench/plot_curves.py "$out/results.json" "$out/time_to_quality.svg"
echo "bench: $out/results.json, $out/results.md, $out/time_to_quality.svg" >&2
