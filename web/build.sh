#!/usr/bin/env bash
# Builds what the page needs: the two browser modules (threaded from build/wasm, the same configuration
# as the wasm test build, so its core is compiled once; single-threaded from build/web-st; both land in
# web/public/wasm/), the precomputed samples (needs build/native's CLI), and with --dist the vite
# bundle in web/dist. Incremental: a second call only rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
export NODE_PATH=/usr/share/nodejs   # em++ needs Debian's acorn (toolchain.md)
jobs=${JOBS:-$(nproc)}
for flavour in mt st; do
  if [ $flavour = mt ]; then
    dir=build/wasm   # tests/build.sh wasm configures it identically
    [ -f "$dir/CMakeCache.txt" ] ||
      emcmake cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DZOME_STRICT=ON -DZOME_UNITY="${ZOME_UNITY:-ON}" >/dev/null
  else
    dir=build/web-st
    [ -f "$dir/CMakeCache.txt" ] ||
      emcmake cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DZOME_STRICT=ON -DZOME_BUILD_TESTS=OFF \
        -DZOME_BUILD_BENCH=OFF -DZOME_WASM_THREADS=OFF -DZOME_UNITY="${ZOME_UNITY:-ON}" >/dev/null
  fi
  echo "build: web-$flavour ($dir)"
  cmake --build "$dir" -j"$jobs" --target zomeify_web
done
[ -x build/native/core/cli/zomeify ] || bash tests/build.sh native
bash web/build_samples.sh
if [ "${1:-}" = "--dist" ]; then
  npx vite build --config web/vite.config.mjs --logLevel warn
fi
