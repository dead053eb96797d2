#pragma once
//! \file face_parts.h
//! The parts of a triangle mesh (faces joined across shared edges), and dropping the vertices that
//! removed faces leave unused.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! One part number per face, numbered in order of each part's first face; `count` gets the number.
std::vector<uint32_t> face_parts(const std::vector<std::array<uint32_t, 3>>& triangles, size_t& count);

//! Removes the vertices no triangle uses, keeping the others in order; `per_vertex` (if given, one
//! entry per vertex) follows.
void drop_unused_vertices(TriangleMesh& mesh, std::vector<uint32_t>* per_vertex = nullptr);

} // namespace zomeify
