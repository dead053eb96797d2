#!/usr/bin/env bash
# The JS unit tests (web/tests/README.md): Node's built-in runner over web/tests/*.test.mjs, no
# browser, no build, no wasm. Prints node's spec report, then exactly one last line
# "tests: N passed, M failed" (cancelled tests count as failed; a runner that crashed before its
# summary counts as 1 failed) and exits non-zero on any failure.
set -uo pipefail
cd "$(dirname "$0")/../.."

tap=$(mktemp)
trap 'rm -f "$tap"' EXIT
# The page's sources are ES modules in .js files and package.json has no "type" (vite and the
# browser do not need it); Node detects the syntax and would warn once per file.
node --disable-warning=MODULE_TYPELESS_PACKAGE_JSON --test --test-timeout=60000 \
  --test-reporter=spec --test-reporter-destination=stdout \
  --test-reporter=tap --test-reporter-destination="$tap" \
  web/tests/*.test.mjs
status=$?

summary() { sed -n "s/^# $1 \([0-9][0-9]*\)$/\1/p" "$tap" | tail -n 1; }
passed=$(summary pass)
failed=$(summary fail)
cancelled=$(summary cancelled)
if [[ -z "$passed" || -z "$failed" ]]; then
  passed=${passed:-0}
  failed=1
else
  failed=$((failed + ${cancelled:-0}))
  if ((status != 0 && failed == 0)); then failed=1; fi
fi
echo "tests: $passed passed, $failed failed"
((failed == 0))
