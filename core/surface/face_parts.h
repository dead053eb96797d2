#pragma once
//! \file face_parts.h
//! The parts of a triangle mesh: faces joined across shared edges.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace zomeify {

//! One part number per face, numbered in order of each part's first face; `count` gets the number.
std::vector<uint32_t> face_parts(const std::vector<std::array<uint32_t, 3>>& triangles, size_t& count);

} // namespace zomeify
