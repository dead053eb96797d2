# libFuzzer targets (tests/fuzz): clang only; tests/build.sh builds them in build/asan beside the sanitized test suite.
# Everything is instrumented for coverage plus ASan and UBSan; only the fuzz executables link libFuzzer.
option(ZOME_BUILD_FUZZ "Build the libFuzzer targets in tests/fuzz (clang, own build dir)" OFF)
if(ZOME_BUILD_FUZZ)
  if(EMSCRIPTEN OR NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "ZOME_BUILD_FUZZ needs clang: CC=clang CXX=clang++ cmake -DZOME_BUILD_FUZZ=ON ...")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
    -fno-omit-frame-pointer -gline-tables-only)
  add_link_options(-fsanitize=address,undefined)
endif()
