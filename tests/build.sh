#!/usr/bin/env bash
# Configures and builds the named flavours:
#   native  build/native     Release, warnings as errors (tests, CLI, benchmarks)
#   wasm    build/wasm       the same core, tests and CLI with Emscripten (pthreads), run under node; its benchmarks
#                            are built by `npm run bench` when it needs them (each wasm link costs ~30 s)
#   asan    build/asan       clang -O2 -g, AddressSanitizer + UndefinedBehaviorSanitizer + libFuzzer coverage:
#                            the whole test suite and the libFuzzer targets of tests/fuzz from one compile
#   tsan    build/tsan-lane  clang -O2 -g with ThreadSanitizer; only the test binary, from the files with *Parallel
#                            suites (the lane runs `ctest -L parallel`)
#   fuzz    the same as asan (kept as a name for tests/fuzz/run.sh)
# The sanitizer builds use clang: with UBSan it compiles this code base about 3x faster than g++ 12. They
# keep line tables only (-gline-tables-only: what sanitizer stack traces print) and precompile the heavy
# headers (cmake/precompiled_headers.cmake).
set -euo pipefail
cd "$(dirname "$0")/.."
export NODE_PATH=/usr/share/nodejs   # emscripten 3.1.6 needs Debian's acorn (toolchain.md)
jobs=$(nproc)
# Every flavour compiles in batches (cmake/unity_build.cmake); ZOME_UNITY=OFF builds one file at a time,
# quicker to rebuild after an edit of one file.
unity=-DZOME_UNITY=${ZOME_UNITY:-ON}
san_flags=(-DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG"
           -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG")
fuzz_targets=(fuzz_obj fuzz_stl fuzz_ply fuzz_off fuzz_gltf fuzz_glb fuzz_vef fuzz_zome_json fuzz_share_link)
for flavour in "$@"; do
  dir="build/$flavour"; targets=()
  case "$flavour" in
    native) cmake -S . -B build/native -DCMAKE_BUILD_TYPE=Release -DZOME_STRICT=ON "$unity" >/dev/null ;;
    wasm)   targets=(zome_tests zomeify)
            emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=Release -DZOME_STRICT=ON "$unity" >/dev/null ;;
    asan|fuzz)
            dir=build/asan
            [ "$flavour" = fuzz ] && targets=("${fuzz_targets[@]}")
            CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${san_flags[@]}" -DZOME_BUILD_FUZZ=ON \
              -DZOME_SANITIZE="address;undefined" -DZOME_BUILD_BENCH=OFF -DZOME_STRICT=ON "$unity" >/dev/null ;;
    tsan)   dir=build/tsan-lane; targets=(zome_tests)
            CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${san_flags[@]}" -DZOME_SANITIZE=thread \
              -DZOME_BUILD_BENCH=OFF -DZOME_PARALLEL_TESTS_ONLY=ON "$unity" >/dev/null ;;
    *) echo "build.sh: unknown flavour '$flavour'" >&2; exit 2 ;;
  esac
  echo "build: $flavour"
  if [ ${#targets[@]} -gt 0 ]; then
    cmake --build "$dir" -j"$jobs" --target "${targets[@]}"
  else
    cmake --build "$dir" -j"$jobs"
  fi
done
