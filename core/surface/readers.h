#pragma once
//! \file readers.h
//! One reader per format, each in its own .cpp; read_mesh.cpp picks one by extension. The messages
//! they throw (InvalidInputError) say what and where but not which file; the caller adds the name.

#include <cstdint>
#include <span>
#include <string>

#include "core/surface/polygon_soup.h"

namespace zomeify::detail {

PolygonSoup read_obj(std::span<const uint8_t> bytes);
//! ASCII or binary, decided by the binary size rule (84 + 50 n bytes), not by the "solid" header.
PolygonSoup read_stl(std::span<const uint8_t> bytes);
PolygonSoup read_ply(std::span<const uint8_t> bytes);
PolygonSoup read_off(std::span<const uint8_t> bytes);
//! glTF (JSON) or GLB. `base_dir` is where external buffers are looked up; empty means the input
//! came from memory, and external buffers are an error.
PolygonSoup read_gltf(std::span<const uint8_t> bytes, bool binary, const std::string& base_dir);

} // namespace zomeify::detail
