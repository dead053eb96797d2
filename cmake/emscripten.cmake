# Flags shared by every Emscripten target. See wasm/README.md for why each one is here.
if(ZOME_WASM_THREADS)
  add_compile_options(-pthread)
  add_link_options(-pthread -sPTHREAD_POOL_SIZE=8)
endif()
# Exceptions carry parse errors to the caller. Debian's frozen cache has libc++abi built for
# JS-emulated exceptions only (no *-wasmexcept variant): with -fwasm-exceptions, catch clauses
# fail to match types. So -fexceptions; hot loops must avoid throwing calls (noexcept) to stay
# free of JS invoke wrappers.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

# Link-time optimisation: clang otherwise inlines nothing across source files, and the annealer's
# hot path crosses several (sample → cache → projector, simulate → energy terms). Measured on the
# bunny (2·10^6 proposals, one thread, pinned): 5.29 s against 5.74 s without, native 4.00 s; the
# same flag on the native GCC build changed nothing measurable, so it is set here only.
if(NOT CMAKE_BUILD_TYPE STREQUAL "Debug")
  add_compile_options(-flto)
  add_link_options(-flto)
endif()

# emcmake injects "node --experimental-wasm-threads", which node 20 rejects; 3.1.6 also needs
# --no-experimental-fetch under node 20 (toolchain.md).
find_program(NODE_EXE node REQUIRED NO_CMAKE_FIND_ROOT_PATH)
set(CMAKE_CROSSCOMPILING_EMULATOR ${NODE_EXE} --no-experimental-fetch CACHE STRING "" FORCE)

# zome_node_program(target): link flags for a program that runs under node (tests, CLI, benchmarks).
# --profiling-funcs keeps function names, so `node --cpu-prof` profiles of these programs are readable
# (it does not change the generated code).
function(zome_node_program target)
  target_link_options(${target} PRIVATE -sENVIRONMENT=node,worker -sEXIT_RUNTIME=1 -sNODERAWFS=1
    -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=256MB -sMAXIMUM_MEMORY=2GB --profiling-funcs)
endfunction()
