#pragma once
//! \file box3.h
//! Axis-aligned box in double precision, used to build the BVH over the input surface.

#include <algorithm>
#include <limits>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! Axis-aligned box. Default-constructed boxes are empty (min = +inf, max = -inf), so extending
//! an empty box by a point gives that point.
struct Box3
{
    Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

    void extend(const Vec3& p)
    {
        min = min.cwiseMin(p);
        max = max.cwiseMax(p);
    }
    void extend(const Box3& b)
    {
        min = min.cwiseMin(b.min);
        max = max.cwiseMax(b.max);
    }
    bool empty() const { return (min.array() > max.array()).any(); }
    Vec3 extent() const { return empty() ? Vec3::Zero() : Vec3(max - min); }
    Vec3 center() const { return 0.5 * (min + max); }
    //! Half the surface area (the SAH only needs ratios); 0 for an empty box.
    double half_area() const
    {
        const Vec3 e = extent();
        return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
    }
    //! Squared distance from `p` to the box (0 inside).
    double distance_squared(const Vec3& p) const
    {
        const Vec3 d = (min - p).cwiseMax(p - max).cwiseMax(0.0);
        return d.squaredNorm();
    }
};

} // namespace zomeify
