#!/usr/bin/env bash
# Configures and builds the named flavours into build/<flavour>:
#   native  Release, warnings as errors (tests, CLI, benchmarks)
#   wasm    the same core, tests, CLI and benchmarks with Emscripten (pthreads), run under node
#   asan    -O2 -g with AddressSanitizer + UndefinedBehaviorSanitizer (optimised so the suite stays quick)
set -euo pipefail
cd "$(dirname "$0")/.."
export NODE_PATH=/usr/share/nodejs   # emscripten 3.1.6 needs Debian's acorn (toolchain.md)
jobs=$(nproc)
for flavour in "$@"; do
  case "$flavour" in
    native) cmake -S . -B build/native -DCMAKE_BUILD_TYPE=Release -DZOME_STRICT=ON >/dev/null ;;
    wasm)   emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=Release -DZOME_STRICT=ON >/dev/null ;;
    asan)   cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZOME_SANITIZE="address;undefined" \
              -DZOME_BUILD_BENCH=OFF >/dev/null ;;
    *) echo "build.sh: unknown flavour '$flavour'" >&2; exit 2 ;;
  esac
  echo "build: $flavour"
  cmake --build "build/$flavour" -j"$jobs"
done
