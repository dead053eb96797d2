#!/usr/bin/env bash
# Every test of the project (the README's test command, `npm test`, calls this):
#   1. native build (warnings as errors) + ctest: GoogleTest suite, CLI contract, fuzz regression corpus
#   2. wasm build + ctest: the same GoogleTest binary and the CLI under node
#   2b. JS unit tests of the page (web/tests/run.sh, node --test; no browser)
#   3. AddressSanitizer + UBSan build + the whole GoogleTest suite and the fuzz regression corpus
#   4. ThreadSanitizer build + the tests labelled `parallel` (ctest -L parallel)
#   5. libFuzzer smoke run: every fuzz target for ZOME_FUZZ_SECONDS (default 10) seconds
#   6. e2e/run.sh (Playwright in Chromium) when it exists
#   0. format: tests/format/check.sh (clang-format --dry-run -Werror over core/ wasm/ tests/), first, once the
#      tree is formatted (tests/format/enforced exists; ZOME_FORMAT=1 runs it before that)
# Ends with one line "tests: N passed, M failed" summing the ctest counts, one per fuzz target and the
# e2e count. For local use, lanes can be skipped: ZOME_SKIP_WASM=1, ZOME_SKIP_ASAN=1, ZOME_SKIP_TSAN=1,
# ZOME_SKIP_FUZZ=1, ZOME_SKIP_E2E=1, ZOME_SKIP_JS=1, ZOME_SKIP_FORMAT=1; ZOME_SKIP_SANITIZERS=1 skips lanes 3-5.
set -uo pipefail
cd "$(dirname "$0")/.."
total_pass=0; total_fail=0; status=0

count() { # count PASSED FAILED
  total_pass=$((total_pass + $1)); total_fail=$((total_fail + $2))
  [ "$2" -eq 0 ] || status=1
}

# Adds the counts of the line "<word> N passed, M failed" in LOG; a missing line is one failure.
count_summary() { # count_summary LOG WORD
  local line; line=$(grep -E "^$2: [0-9]+ passed, [0-9]+ failed" "$1" | tail -1)
  if [ -z "$line" ]; then count 0 1; return; fi
  count "$(sed -E 's/.*: ([0-9]+) passed.*/\1/' <<<"$line")" "$(sed -E 's/.*passed, ([0-9]+) failed.*/\1/' <<<"$line")"
}

run_ctest() { # run_ctest DIR [ctest args]
  local dir="$1"; shift
  local log; log=$(mktemp)
  (cd "$dir" && ctest --output-on-failure --timeout 1500 -j"$(nproc)" "$@") 2>&1 | tee "$log"
  local line; line=$(grep -E 'tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -1)
  if [ -z "$line" ]; then
    if grep -q 'No tests were found' "$log"; then
      echo "run_all: no tests matched in $dir ($*): nothing to count"
    else
      count 0 1
    fi
    rm -f "$log"; return
  fi
  local failed total
  failed=$(sed -E 's/.*passed, ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
  total=$(sed -E 's/.*failed out of ([0-9]+).*/\1/' <<<"$line")
  count $((total - failed)) "$failed"
  rm -f "$log"
}

skip() { [ "${!1:-0}" = 1 ]; }

# Wall time of each lane, printed together at the end (CI must stay under 45 minutes).
lane_times=(); lane_start=$SECONDS
lane_done() { # lane_done NAME
  lane_times+=("$(printf '%-10s %4d s' "$1" $((SECONDS - lane_start)))"); lane_start=$SECONDS
}
print_lane_times() { echo "lane times:"; printf '  %s\n' "${lane_times[@]}"; }
sanitizers=1; skip ZOME_SKIP_SANITIZERS && sanitizers=0

if ! skip ZOME_SKIP_FORMAT && { [ -f tests/format/enforced ] || [ "${ZOME_FORMAT:-0}" = 1 ]; }; then
  if bash tests/format/check.sh; then count 1 0; else count 0 1; fi
  lane_done format
else
  echo "format lane: off until the tree is formatted (tests/format/README.md)"
fi

bash tests/build.sh native || { echo "tests: 0 passed, 1 failed"; exit 1; }
# The tests labelled parallel (suites *Parallel, tests/CMakeLists.txt) rerun the multi-threaded tests for the TSan lane;
# the other lanes already run each of them once.
run_ctest build/native -LE parallel
command -v blender >/dev/null 2>&1 || echo "blender_colours_native: skipped: Blender not installed (tests/README.md)"
lane_done native
if ! skip ZOME_SKIP_WASM; then
  bash tests/build.sh wasm || { echo "tests: $total_pass passed, $((total_fail + 1)) failed"; exit 1; }
  run_ctest build/wasm
  lane_done wasm
fi
if [ -f web/tests/run.sh ] && ! skip ZOME_SKIP_JS; then
  log=$(mktemp)
  bash web/tests/run.sh 2>&1 | tee "$log"
  count_summary "$log" tests
  rm -f "$log"
  lane_done js
fi
if [ $sanitizers = 1 ] && ! skip ZOME_SKIP_ASAN; then
  bash tests/build.sh asan || { echo "tests: $total_pass passed, $((total_fail + 1)) failed"; exit 1; }
  # The sweeps over every shared mesh listed in tests/asan_sweeps.txt run in the native and wasm lanes only.
  sweeps=$(grep -vE '^(#|$)' tests/asan_sweeps.txt | sed 's/\./\\./g' | paste -sd'|')
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 run_ctest build/asan -LE parallel -E "^($sweeps)\$"
  lane_done asan
fi
if [ $sanitizers = 1 ] && ! skip ZOME_SKIP_TSAN; then
  if bash tests/build.sh tsan; then
    echo "tsan lane: tests labelled 'parallel':"
    (cd build/tsan-lane && ctest -N -L parallel | grep -E 'Test +#|Total Tests')
    ZOME_STRESS_SECONDS=60 TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" run_ctest build/tsan-lane -L parallel
  else
    count 0 1
  fi
  lane_done tsan
fi
if [ $sanitizers = 1 ] && ! skip ZOME_SKIP_FUZZ; then
  log=$(mktemp)
  bash tests/fuzz/run.sh "${ZOME_FUZZ_SECONDS:-10}" 2>&1 | tee "$log"
  count_summary "$log" fuzz
  rm -f "$log"
  lane_done fuzz
fi
if [ -f e2e/run.sh ] && ! skip ZOME_SKIP_E2E; then
  # e2e/run.sh may print its own "tests: N passed, M failed"; otherwise its exit status is one result.
  log=$(mktemp)
  bash e2e/run.sh 2>&1 | tee "$log"; rc=${PIPESTATUS[0]}
  if grep -qE '^tests: [0-9]+ passed, [0-9]+ failed' "$log"; then
    count_summary "$log" tests
  elif [ "$rc" -eq 0 ]; then count 1 0; else count 0 1; fi
  rm -f "$log"
  lane_done e2e
fi

print_lane_times

echo "tests: $total_pass passed, $total_fail failed"
exit $status
