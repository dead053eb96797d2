# Flags shared by every Emscripten target. See wasm/README.md for why each one is here.
if(ZOME_WASM_THREADS)
  add_compile_options(-pthread)
  add_link_options(-pthread -sPTHREAD_POOL_SIZE=8)
endif()
# Exceptions carry parse errors to the caller; native wasm exceptions keep the hot paths free of
# JS invoke wrappers (JS-emulated exceptions would wrap every call that may throw).
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions -sUSE_ZLIB=1)
add_compile_options(-sUSE_ZLIB=1)

# emcmake injects "node --experimental-wasm-threads", which node 20 rejects; 3.1.6 also needs
# --no-experimental-fetch under node 20 (toolchain.md).
find_program(NODE_EXE node REQUIRED NO_CMAKE_FIND_ROOT_PATH)
set(CMAKE_CROSSCOMPILING_EMULATOR ${NODE_EXE} --no-experimental-fetch CACHE STRING "" FORCE)

# zome_node_program(target): link flags for a program that runs under node (tests, CLI, benchmarks).
function(zome_node_program target)
  target_link_options(${target} PRIVATE -sENVIRONMENT=node,worker -sEXIT_RUNTIME=1 -sNODERAWFS=1
    -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=256MB -sMAXIMUM_MEMORY=2GB)
endfunction()
