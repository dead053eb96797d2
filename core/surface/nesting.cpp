#include "core/surface/nesting.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

namespace zomeify {

namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

// Pairs of components and triangles per pair bound the work; hostile files with very many shells
// get no cavity detection rather than a quadratic hang.
constexpr size_t max_components = 1000;
constexpr size_t max_solid_angles = 50'000'000;

// Solid angle of triangle abc seen from the origin (Van Oosterom and Strackee), signed by the
// triangle's orientation.
double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c)
{
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    return 2 * std::atan2(numerator, denominator);
}

// The closed components: bounding box, triangles and corners of each.
struct ClosedParts
{
    std::vector<Vec3> lo, hi;
    std::vector<std::vector<uint32_t>> faces;
    std::vector<std::vector<uint32_t>> corners; // one vertex per triangle, in order
    size_t count = 0;

    bool box_holds(size_t d, const Vec3& p) const
    {
        return (p.array() >= lo[d].array()).all() && (p.array() <= hi[d].array()).all();
    }
};

ClosedParts gather(const std::vector<Vec3>& positions, const Triangles& triangles,
                   const std::vector<uint32_t>& component, const std::vector<uint8_t>& closed)
{
    const size_t nc = closed.size();
    const double inf = std::numeric_limits<double>::infinity();
    ClosedParts parts{std::vector<Vec3>(nc, Vec3::Constant(inf)), std::vector<Vec3>(nc, Vec3::Constant(-inf)),
                      std::vector<std::vector<uint32_t>>(nc), std::vector<std::vector<uint32_t>>(nc), 0};
    for (const uint8_t c : closed)
        parts.count += c;
    for (uint32_t f = 0; f < triangles.size(); ++f)
    {
        const uint32_t c = component[f];
        if (!closed[c])
            continue;
        parts.faces[c].push_back(f);
        parts.corners[c].push_back(triangles[f][0]);
        for (const uint32_t v : triangles[f])
        {
            parts.lo[c] = parts.lo[c].cwiseMin(positions[v]);
            parts.hi[c] = parts.hi[c].cwiseMax(positions[v]);
        }
    }
    return parts;
}

// The winding number of closed component d at p: ±1 inside, 0 outside, 0.5 on the surface.
double winding(const std::vector<Vec3>& positions, const Triangles& triangles, const std::vector<uint32_t>& faces,
               const Vec3& p)
{
    double omega = 0;
    for (const uint32_t f : faces)
        omega +=
            solid_angle(positions[triangles[f][0]] - p, positions[triangles[f][1]] - p, positions[triangles[f][2]] - p);
    return std::abs(omega) / (4 * std::numbers::pi);
}

} // namespace

std::vector<uint32_t> nesting_depths(const std::vector<Vec3>& positions, const Triangles& triangles,
                                     const std::vector<uint32_t>& component, const std::vector<uint8_t>& closed)
{
    const size_t nc = closed.size();
    std::vector<uint32_t> depth(nc, 0);
    const ClosedParts parts = gather(positions, triangles, component, closed);
    if (parts.count < 2 || parts.count > max_components)
        return depth;
    size_t work = 0;
    for (size_t c = 0; c < nc; ++c)
    {
        if (!closed[c])
            continue;
        // Three corners far apart in the face order: a part that overlaps another has some inside
        // and some outside, and is no cavity.
        const std::vector<uint32_t>& corners = parts.corners[c];
        const uint32_t probes[3] = {corners.front(), corners[corners.size() / 2], corners.back()};
        for (size_t d = 0; d < nc; ++d)
        {
            if (d == c || !closed[d])
                continue;
            bool enclosed = true;
            for (const uint32_t v : probes)
            {
                const Vec3& p = positions[v];
                if (!parts.box_holds(d, p))
                {
                    enclosed = false;
                    break;
                }
                work += parts.faces[d].size();
                if (work > max_solid_angles)
                    return std::vector<uint32_t>(nc, 0);
                if (winding(positions, triangles, parts.faces[d], p) <= 0.5)
                {
                    enclosed = false;
                    break;
                }
            }
            depth[c] += enclosed;
        }
    }
    return depth;
}

} // namespace zomeify
