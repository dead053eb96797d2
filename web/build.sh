#!/usr/bin/env bash
# Builds what the page needs: the two browser modules (threaded build/web-mt, single-threaded
# build/web-st → web/public/wasm/), the precomputed samples (needs build/native's CLI), and with
# --dist the vite bundle in web/dist. Incremental: a second call only rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
export NODE_PATH=/usr/share/nodejs   # em++ needs Debian's acorn (toolchain.md)
jobs=${JOBS:-$(nproc)}
for flavour in mt st; do
  dir=build/web-$flavour
  threads=ON; [ $flavour = st ] && threads=OFF
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    emcmake cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DZOME_STRICT=ON -DZOME_BUILD_TESTS=OFF \
      -DZOME_BUILD_BENCH=OFF -DZOME_WASM_THREADS=$threads >/dev/null
  fi
  echo "build: web-$flavour"
  cmake --build "$dir" -j"$jobs" --target zomeify_web
done
[ -x build/native/core/cli/zomeify ] || bash tests/build.sh native
bash web/build_samples.sh
if [ "${1:-}" = "--dist" ]; then
  npx vite build --config web/vite.config.mjs --logLevel warn
fi
