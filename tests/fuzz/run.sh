#!/usr/bin/env bash
# Runs each fuzz target for SECONDS (all targets when none is named), one per core at a time, at low priority.
#   tests/fuzz/run.sh SECONDS [TARGET...]       targets: obj stl ply off gltf glb vef zome_json share_link
# Environment: FUZZ_RUNS=N also stops a target after N executions; FUZZ_NICE (default 15);
# FUZZ_RSS_MB (default 2048); FUZZ_TIMEOUT seconds per input before it counts as a hang (default 10);
# FUZZ_RESULTS another results file (so that two runs of this script on different targets can share the machine).
# Builds the targets in build/asan if needed (tests/build.sh fuzz), generates seeds from ../shared into build/fuzz/seeds, keeps each target's
# growing corpus in build/fuzz/corpus/<target>, findings in build/fuzz/findings/<target>/, one line
# per target in build/fuzz/results.tsv, and ends with "fuzz: N passed, M failed" (a target passes
# when it ran its time without a crash, hang, leak or broken invariant).
set -uo pipefail
cd "$(dirname "$0")/../.."
all_targets=(obj stl ply off gltf glb vef zome_json share_link)
seconds=${1:?usage: tests/fuzz/run.sh SECONDS [TARGET...]}; shift
targets=("$@"); [ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")
shared=${ZOME_SHARED_DIR:-../shared}
bin=build/asan/tests/fuzz
dir=build/fuzz; mkdir -p "$dir"

if [ ! -x "$bin/fuzz_${targets[0]}" ] || [ "${FUZZ_REBUILD:-0}" = 1 ]; then
  bash tests/build.sh fuzz >/dev/null || { echo "fuzz: 0 passed, 1 failed (build)"; exit 1; }
fi
if [ ! -d "$dir/seeds" ]; then
  # .zome.json and share-link seeds come from the CLI of the native build, when there is one.
  cli=(); [ -x build/native/core/cli/zomeify ] && cli=(build/native/core/cli/zomeify)
  python3 tests/fuzz/make_seeds.py "$shared" "$dir/seeds" "${cli[@]}" >&2 ||
    { echo "fuzz: 0 passed, 1 failed (seeds)"; exit 1; }
fi

max_len() { # inputs larger than this are cut: small inputs mutate and run faster, and the seeds' first
  # kilobytes already hold every construct of their format
  case "$1" in
    vef) echo 16384 ;;
    share_link) echo 4096 ;;
    *) echo 8192 ;;
  esac
}

results=${FUZZ_RESULTS:-$dir/results.tsv}
printf 'target\tseconds\texecutions\texec_per_s\tpeak_rss_mb\tcorpus\tresult\n' > "$results"
run_target() { # run_target T: fuzzes T, writes its results line to $dir/logs/T.result
  local t=$1 exe="$bin/fuzz_$1"
  mkdir -p "$dir/corpus/$t" "$dir/findings/$t" "$dir/logs"
  local log="$dir/logs/$t.log"
  local runs=(); [ -n "${FUZZ_RUNS:-}" ] && runs=(-runs="$FUZZ_RUNS")
  local start; start=$(date +%s)
  # Extra corpus folders are read only; new inputs go to the first one.
  nice -n "${FUZZ_NICE:-15}" "$exe" -max_total_time="$seconds" "${runs[@]}" -max_len="$(max_len "$t")" \
    -rss_limit_mb="${FUZZ_RSS_MB:-2048}" -timeout="${FUZZ_TIMEOUT:-10}" -print_final_stats=1 \
    -artifact_prefix="$dir/findings/$t/" "$dir/corpus/$t" "$dir/seeds/$t" tests/fuzz/seeds/$t \
    $( [ -d tests/fuzz/regressions/$t ] && echo tests/fuzz/regressions/$t ) >"$log" 2>&1
  local rc=$?
  local elapsed=$(( $(date +%s) - start ))
  local execs rate rss corpus result
  execs=$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+)/\1/p' "$log" | tail -1)
  rate=$(sed -nE 's/^stat::average_exec_per_sec: *([0-9]+)/\1/p' "$log" | tail -1)
  rss=$(sed -nE 's/^stat::peak_rss_mb: *([0-9]+)/\1/p' "$log" | tail -1)
  corpus=$(find "$dir/corpus/$t" -type f | wc -l)
  if [ "$rc" -eq 0 ]; then result=ok; else
    result="FINDING (exit $rc): $(grep -m1 -E 'ERROR: |runtime error|invariant broken|==ERROR' "$log" | cut -c1-160)"
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$t" "$elapsed" "${execs:-?}" "${rate:-?}" "${rss:-?}" "$corpus" "$result" \
    > "$dir/logs/$t.result"
}

# FUZZ_JOBS targets at a time (default: one per core); each target's time is its own.
jobs=${FUZZ_JOBS:-$(nproc)}; running=0; known=()
for t in "${targets[@]}"; do
  [ -x "$bin/fuzz_$t" ] || { echo "fuzz: unknown target '$t'" >&2; continue; }
  known+=("$t"); rm -f "$dir/logs/$t.result"
  run_target "$t" & running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
done
wait
passed=0; failed=$(( ${#targets[@]} - ${#known[@]} ))
for t in "${known[@]}"; do
  line=$(cat "$dir/logs/$t.result" 2>/dev/null) || line=$(printf '%s\t?\t?\t?\t?\t?\tno result' "$t")
  echo "$line" | tee -a "$results"
  if [ "$(cut -f7 <<<"$line")" = ok ]; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
done
echo "fuzz: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
