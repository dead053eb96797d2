#pragma once
//! \file tiny_gltf_config.h
//! tinygltf with the one configuration every translation unit must share (the options change the
//! TinyGLTF class's defaults, so mixing them would break the one-definition rule): no image
//! decoding or encoding, no external images.

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
