#pragma once
//! \file triangle_mesh.h
//! The input surface S after import and repair: an indexed triangle mesh in the input's units,
//! faces counter-clockwise seen from outside. Produced by core/surface, read by geom and voxel.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace zomeify {

using Vec3 = Eigen::Vector3d;

struct TriangleMesh
{
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;
};

} // namespace zomeify
