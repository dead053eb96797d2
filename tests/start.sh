#!/usr/bin/env bash
# `npm start`: builds what is missing (native CLI, browser modules, samples, vite bundle) and
# serves the page on localhost with COOP/COEP, printing its address. PORT=… picks the port.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/native/core/cli/zomeify ] || bash tests/build.sh native
bash web/build.sh --dist
export PORT=${PORT:-8080}
echo "Open the address below in Chromium, Firefox or Safari (Ctrl+C stops the server)."
exec env ROOT=dist node web/server.mjs
