#include "core/voxel/tri_box.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace zomeify {

namespace {

// Projections of the triangle onto an axis separate it from the box (radius r about 0)?
// Closed contact: touching intervals do not separate; open contact: they do.
bool separated(double lo, double hi, double r, BoxContact contact)
{
    if (contact == BoxContact::Closed)
        return lo > r || hi < -r;
    return lo >= r || hi <= -r;
}

bool separated_on(const Vec3& axis, const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& half,
                  BoxContact contact)
{
    // A vanishing axis (edge parallel to a box axis, or a degenerate triangle) proves nothing;
    // the remaining axes still decide, because the separating axis theorem only needs the
    // non-degenerate ones for a flat convex polygon against a box.
    if (axis.squaredNorm() == 0.0)
        return false;
    const double p0 = axis.dot(v0), p1 = axis.dot(v1), p2 = axis.dot(v2);
    const double r = half.x() * std::abs(axis.x()) + half.y() * std::abs(axis.y()) + half.z() * std::abs(axis.z());
    return separated(std::min({p0, p1, p2}), std::max({p0, p1, p2}), r, contact);
}

} // namespace

bool triangle_box_overlap(const Vec3& centre, const Vec3& half, const Vec3& a, const Vec3& b, const Vec3& c,
                          BoxContact contact)
{
    const Vec3 v0 = a - centre, v1 = b - centre, v2 = c - centre;

    // Box face normals first: they reject most candidates and cost the least.
    for (int k = 0; k < 3; ++k)
    {
        const double lo = std::min({v0[k], v1[k], v2[k]});
        const double hi = std::max({v0[k], v1[k], v2[k]});
        if (separated(lo, hi, half[k], contact))
            return false;
    }

    const Vec3 e0 = v1 - v0, e1 = v2 - v1, e2 = v0 - v2;
    if (separated_on(e0.cross(e1), v0, v1, v2, half, contact))
        return false;

    const Vec3 edges[3] = {e0, e1, e2};
    for (const Vec3& e : edges)
        for (int k = 0; k < 3; ++k)
            if (separated_on(e.cross(Vec3::Unit(k)), v0, v1, v2, half, contact))
                return false;
    return true;
}

} // namespace zomeify
