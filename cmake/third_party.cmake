# Header-only dependencies from Debian's packages. For Emscripten we must never add -I/usr/include
# (host libc headers), so the few headers we need are staged into the build tree for both targets.
find_package(Eigen3 3.4 REQUIRED NO_MODULE NO_CMAKE_FIND_ROOT_PATH)
find_path(TINYGLTF_INC tiny_gltf.h PATHS /usr/include NO_CMAKE_FIND_ROOT_PATH REQUIRED)
find_path(NLOHMANN_INC nlohmann/json.hpp PATHS /usr/include NO_CMAKE_FIND_ROOT_PATH REQUIRED)
set(ZOME_TP_INC ${CMAKE_BINARY_DIR}/tp_inc)
file(COPY ${TINYGLTF_INC}/tiny_gltf.h DESTINATION ${ZOME_TP_INC})
file(COPY ${NLOHMANN_INC}/nlohmann DESTINATION ${ZOME_TP_INC})
