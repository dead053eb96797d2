#!/usr/bin/env bash
# Configures and builds the named flavours:
#   native  build/native     Release, warnings as errors (tests, CLI, benchmarks)
#   wasm    build/wasm       the same core, tests, CLI and benchmarks with Emscripten (pthreads), run under node
#   asan    build/asan       -O2 -g with AddressSanitizer + UndefinedBehaviorSanitizer (optimised so the suite stays quick)
#   tsan    build/tsan-lane  -O2 -g with ThreadSanitizer; only the test binary (the lane runs `ctest -L parallel`)
#   fuzz    build/fuzz       clang libFuzzer targets with ASan + UBSan (tests/fuzz); only the fuzz executables
set -euo pipefail
cd "$(dirname "$0")/.."
export NODE_PATH=/usr/share/nodejs   # emscripten 3.1.6 needs Debian's acorn (toolchain.md)
jobs=$(nproc)
fuzz_targets=(fuzz_obj fuzz_stl fuzz_ply fuzz_off fuzz_gltf fuzz_glb fuzz_vef fuzz_zome_json fuzz_share_link)
for flavour in "$@"; do
  dir="build/$flavour"; targets=()
  case "$flavour" in
    native) cmake -S . -B build/native -DCMAKE_BUILD_TYPE=Release -DZOME_STRICT=ON >/dev/null ;;
    wasm)   emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=Release -DZOME_STRICT=ON >/dev/null ;;
    asan)   cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZOME_SANITIZE="address;undefined" \
              -DZOME_BUILD_BENCH=OFF >/dev/null ;;
    tsan)   dir=build/tsan-lane; targets=(zome_tests)
            cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZOME_SANITIZE=thread \
              -DZOME_BUILD_BENCH=OFF >/dev/null ;;
    fuzz)   targets=("${fuzz_targets[@]}")
            CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZOME_BUILD_FUZZ=ON \
              -DZOME_BUILD_TESTS=OFF -DZOME_BUILD_BENCH=OFF -DZOME_STRICT=ON >/dev/null ;;
    *) echo "build.sh: unknown flavour '$flavour'" >&2; exit 2 ;;
  esac
  echo "build: $flavour"
  if [ ${#targets[@]} -gt 0 ]; then
    cmake --build "$dir" -j"$jobs" --target "${targets[@]}"
  else
    cmake --build "$dir" -j"$jobs"
  fi
done
