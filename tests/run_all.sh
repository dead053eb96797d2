#!/usr/bin/env bash
# Every test of the project (the README's test command, `npm test`, calls this):
#   1. native build (warnings as errors) + ctest: GoogleTest suite and the CLI contract
#   2. wasm build + ctest: the same GoogleTest binary and the CLI under node
#   3. AddressSanitizer + UBSan build + the whole GoogleTest suite
# Ends with one line "tests: N passed, M failed" summing the ctest counts.
set -uo pipefail
cd "$(dirname "$0")/.."
total_pass=0; total_fail=0; status=0

run_ctest() { # run_ctest FLAVOUR [ctest args]
  local dir="build/$1"; shift
  local log; log=$(mktemp)
  (cd "$dir" && ctest --output-on-failure --timeout 1500 -j"$(nproc)" "$@") 2>&1 | tee "$log"
  local line; line=$(grep -E 'tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -1)
  if [ -z "$line" ]; then status=1; total_fail=$((total_fail + 1)); rm -f "$log"; return; fi
  local failed total
  failed=$(sed -E 's/.*passed, ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
  total=$(sed -E 's/.*failed out of ([0-9]+).*/\1/' <<<"$line")
  total_pass=$((total_pass + total - failed)); total_fail=$((total_fail + failed))
  [ "$failed" -eq 0 ] || status=1
  rm -f "$log"
}

bash tests/build.sh native || { echo "tests: 0 passed, 1 failed"; exit 1; }
run_ctest native
bash tests/build.sh wasm || { echo "tests: $total_pass passed, $((total_fail + 1)) failed"; exit 1; }
run_ctest wasm
if [ "${ZOME_SKIP_SANITIZERS:-0}" != 1 ]; then
  bash tests/build.sh asan || { echo "tests: $total_pass passed, $((total_fail + 1)) failed"; exit 1; }
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 run_ctest asan
fi

echo "tests: $total_pass passed, $total_fail failed"
exit $status
