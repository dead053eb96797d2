// The one translation unit that compiles tinygltf (Debian's shared library is of no use to the
// wasm build). Images are never decoded: the reader only needs geometry.
#define TINYGLTF_IMPLEMENTATION
#include "core/surface/tiny_gltf_config.h"
