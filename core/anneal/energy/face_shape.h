#pragma once
//! \file face_shape.h
//! A face of the model as geometry: its canonical triangles (face_triangles.h) in b0 units, with a
//! box and the triangles' normals, and its distance to a point.

#include <array>
#include <cstdint>
#include <span>

#include "core/geom/box3.h"
#include "core/zome/zvec.h"

namespace zomeify {

//! A face as the energy and the clearance checks see it.
struct FaceShape
{
    std::array<std::array<Vec3, 3>, 2> triangles{};
    //! Unit normal of each triangle (zero for a degenerate one), for a cheap lower bound.
    std::array<Vec3, 2> normals{};
    int count = 0; //!< triangles (1 or 2)
    Box3 box;
};

//! The canonical triangles of a face of 3 or 4 corners (counter-clockwise seen from outside).
FaceShape face_shape(std::span<const ZVec> corners) noexcept;

//! Squared distance from p to the face (its nearest triangle).
double face_distance_squared(const Vec3& p, const FaceShape& face) noexcept;

//! face_distance_squared(p, face) if it is below `bound`, otherwise a lower bound of it (≥ bound)
//! (a face is skipped when its box or the planes of its triangles are farther than bound): the
//! same result wherever it is below the bound, for far less work on the many faces that lose.
double face_distance_squared_below(const Vec3& p, const FaceShape& face, double bound) noexcept;

} // namespace zomeify
