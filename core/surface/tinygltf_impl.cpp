// The one translation unit that compiles tinygltf (Debian ships it header-only for our purposes;
// its shared library is of no use to the wasm build). Images are never decoded: the reader only
// needs geometry, and it installs an image loader that skips them.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
