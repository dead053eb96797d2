# Precompiled headers for the clang builds (Emscripten, the ASan/UBSan/fuzz and TSan lanes). The standard library,
# Eigen and nlohmann/json are ~190k preprocessed lines in every translation unit (GoogleTest 100k more
# in the tests); with the templates they instantiate, parsing them was a third of each compile under
# the sanitizers: clang -O2 with ASan+UBSan, annealer_test.cpp 6.6 -> 4.5 s, pipeline.cpp 7.0 ->
# 4.4 s with a PCH holding its template instantiations (CMake passes -fpch-instantiate-templates).
# Emscripten (-flto: compiling is mostly parsing, the optimizer runs at the link): 4.4 -> 2.0 s and
# 3.6 -> 1.8 s. Off for g++ (the native lane: 11-18 % on big files, small files 3x slower);
# -DZOME_PCH=ON/OFF overrides.
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  set(_zome_pch_default ON)
else()
  set(_zome_pch_default OFF)
endif()
option(ZOME_PCH "Precompile the standard library, Eigen and nlohmann/json headers" ${_zome_pch_default})

set(ZOME_PCH_HEADERS <algorithm> <array> <atomic> <cmath> <cstddef> <cstdint> <cstdio> <functional> <limits>
  <map> <memory> <optional> <random> <set> <span> <sstream> <string> <string_view> <unordered_map> <utility>
  <vector> <Eigen/Geometry> <nlohmann/json.hpp>)

# zome_precompile(TARGET [EXTRA_HEADER ...]): the shared list plus the target's own heavy headers.
function(zome_precompile target)
  if(ZOME_PCH)
    target_precompile_headers(${target} PRIVATE ${ZOME_PCH_HEADERS} ${ARGN})
  endif()
endfunction()
