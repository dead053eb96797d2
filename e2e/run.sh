#!/usr/bin/env bash
# Builds what the page needs (assumes build/native exists) and runs the Playwright tests headless
# in Debian's Chromium. Extra arguments go to Playwright (e.g. a spec file, -g "cancel").
# Ends with "tests: N passed, M failed" (what tests/run_all.sh counts).
#   bash e2e/run.sh                  # against the sources (web/server.mjs)
#   E2E_ROOT=dist bash e2e/run.sh    # against the vite bundle
set -uo pipefail
cd "$(dirname "$0")/.."
[ -d node_modules/@playwright/test ] || npm ci --no-audit --no-fund
build=(bash web/build.sh); [ "${E2E_ROOT:-}" = dist ] && build+=(--dist)
if ! "${build[@]}"; then
  echo "e2e: building the page failed"
  echo "tests: 0 passed, 1 failed"
  exit 1
fi
log=$(mktemp)
(cd e2e && npx playwright test -c playwright.config.js "$@") 2>&1 | tee "$log"
rc=${PIPESTATUS[0]}
# Playwright's closing lines: "  14 passed (1.2m)", "  1 failed", "  2 flaky", "  3 did not run".
passed=$(awk '/^ +[0-9]+ passed/ {n = $1} END {print n + 0}' "$log")
failed=$(awk '/^ +[0-9]+ (failed|flaky|interrupted|did not run)/ {n += $1} END {print n + 0}' "$log")
rm -f "$log"
[ "$rc" -ne 0 ] && [ "$failed" -eq 0 ] && failed=1
echo "tests: $passed passed, $failed failed"
exit "$rc"
