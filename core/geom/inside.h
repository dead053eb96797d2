#pragma once
//! \file inside.h
//! Inside/outside of the input surface and signed distance, by angle-weighted pseudo-normals
//! (Bærentzen & Aanæs, "Signed distance computation using the angle weighted pseudonormal", 2005).
//! The annealer's forbidden zone (design §3.3) needs the side of every sample next to π(p).

#include <array>
#include <cstdint>
#include <vector>

#include "core/geom/closest_point.h"

namespace zomeify {

//! For a closed, consistently outward-oriented 2-manifold S, p lies inside iff
//! (p − π(p))·n < 0, where n is the pseudo-normal of the feature holding π(p): the face normal on
//! a face, the sum of the two face normals on an edge, the angle-weighted normal at a vertex.
//! This is exact for any p off S (up to rounding near S); points on S count as outside.
//! Holds a reference to the projector, which must outlive it. Thread-safe const queries.
class InsideTest
{
public:
    explicit InsideTest(const SurfaceProjector& projector);

    //! True if p is strictly inside S.
    bool is_inside(const Vec3& p) const;
    //! Same, reusing an answer of projector.project(p) (the annealer has it already).
    bool is_inside(const Vec3& p, const ClosestPoint& closest) const;
    //! ‖p − π(p)‖, negative inside S.
    double signed_distance(const Vec3& p) const;
    //! The pseudo-normal used for a given closest feature of triangle `t` (not normalised).
    Vec3 pseudo_normal(uint32_t t, TriangleFeature feature) const;

    const SurfaceProjector& projector() const { return projector_; }

private:
    const SurfaceProjector& projector_;
    //! Per triangle, the pseudo-normals of its edges 01, 12, 20.
    std::vector<std::array<Vec3, 3>> edge_normals_;
};

} // namespace zomeify
