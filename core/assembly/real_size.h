#pragma once
//! \file real_size.h
//! The built size a person asks for ("about 50 cm tall") as the scale of a run: the voxel edge b1 in
//! mesh units that makes the longest side of the built model (ball centres plus one ball) that long,
//! taking the model to span the mesh's longest bounding-box side.

#include <array>

namespace zomeify {

//! b1 in mesh units for a built longest side of `size_cm`; throws InvalidInputError when the size
//! gives fewer than 2 or more than 256 cells along that side, or the mesh is flat.
double b1_for_size_cm(double mesh_longest_side, double size_cm);

//! The built longest side in cm of a model whose ball centres span `extent_b0` (b0 = 1).
double built_size_cm(double extent_b0);

} // namespace zomeify
