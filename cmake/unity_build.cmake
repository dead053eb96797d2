# Unity builds: with ZOME_UNITY=ON every target compiles its sources in batches of 8 (CMake's
# UNITY_BUILD), so the headers and the inline and template code they instantiate are compiled once
# per batch rather than once per file. On the 2-core VM, from scratch: the ASan+UBSan build of
# everything 371 -> 223 s, the native g++ build 897 -> 434 CPU seconds (docs/perf-log.md). Off here,
# on in tests/build.sh and web/build.sh (ZOME_UNITY=OFF there: one file at a time, quicker to rebuild
# after an edit, since an edit recompiles its whole batch). Files whose file-local names
# clash with a batch-mate's keep their own translation unit (SKIP_UNITY_BUILD_INCLUSION in
# core/CMakeLists.txt and tests/CMakeLists.txt); a new clash is a compile error in these builds.
option(ZOME_UNITY "Compile each target's sources in batches (faster builds from scratch)" OFF)
if(ZOME_UNITY)
  set(CMAKE_UNITY_BUILD ON)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE 8)
endif()
