#!/usr/bin/env bash
# Builds what the page needs (assumes build/native exists) and runs the Playwright tests headless
# in Debian's Chromium. Extra arguments go to Playwright (e.g. a spec file, -g "cancel").
#   bash e2e/run.sh                  # against the sources (web/server.mjs)
#   E2E_ROOT=dist bash e2e/run.sh    # against the vite bundle
set -euo pipefail
cd "$(dirname "$0")/.."
[ -d node_modules/@playwright/test ] || npm ci --no-audit --no-fund
if [ "${E2E_ROOT:-}" = dist ]; then bash web/build.sh --dist; else bash web/build.sh; fi
cd e2e
exec npx playwright test -c playwright.config.js "$@"
