#pragma once
//! \file read_mesh.h
//! Reads a mesh file into a PolygonSoup. The format comes from the file name's extension
//! (case-insensitive): .obj .stl .ply .off .gltf .glb. Every reader treats its input as hostile:
//! counts are checked against the data size before anything is allocated, coordinates must be
//! finite and indices in range. Problems raise InvalidInputError with a one-line message naming
//! the file, the problem and where it is (line number or element index); IoError if a file cannot be read.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "core/surface/polygon_soup.h"

namespace zomeify {

//! Reads the file at `path`. A .gltf may refer to external buffers next to it.
PolygonSoup read_mesh_file(const std::string& path);

//! Reads a file already in memory (the page's dropped file). `file_name` selects the format and
//! names the input in messages. A .gltf read this way can only use embedded (data:) buffers.
PolygonSoup read_mesh_buffer(std::span<const uint8_t> bytes, std::string_view file_name);

//! True if the extension of `file_name` is one of the formats above.
bool is_mesh_file_name(std::string_view file_name);

} // namespace zomeify
