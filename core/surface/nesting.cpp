#include "core/surface/nesting.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

namespace zomeify {

namespace {

// Solid angle of triangle abc seen from the origin (Van Oosterom and Strackee), signed by the
// triangle's orientation.
double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c)
{
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    return 2 * std::atan2(numerator, denominator);
}

} // namespace

std::vector<uint32_t> nesting_depths(const std::vector<Vec3>& positions,
                                     const std::vector<std::array<uint32_t, 3>>& triangles,
                                     const std::vector<uint32_t>& component, const std::vector<uint8_t>& closed)
{
    const size_t nc = closed.size();
    std::vector<uint32_t> depth(nc, 0);
    size_t closed_count = 0;
    for (const uint8_t c : closed)
        closed_count += c;
    // Pairs of components and triangles per pair bound the work; hostile files with very many
    // shells get no cavity detection rather than a quadratic hang.
    constexpr size_t max_components = 1000;
    constexpr size_t max_solid_angles = 50'000'000;
    if (closed_count < 2 || closed_count > max_components)
        return depth;

    // Per component: bounding box, one vertex (the query point) and its triangles.
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<Vec3> lo(nc, Vec3::Constant(inf)), hi(nc, Vec3::Constant(-inf));
    std::vector<uint32_t> probe(nc, std::numeric_limits<uint32_t>::max());
    std::vector<std::vector<uint32_t>> faces(nc);
    for (uint32_t f = 0; f < triangles.size(); ++f)
    {
        const uint32_t c = component[f];
        if (!closed[c])
            continue;
        faces[c].push_back(f);
        if (probe[c] == std::numeric_limits<uint32_t>::max())
            probe[c] = triangles[f][0];
        for (const uint32_t v : triangles[f])
        {
            lo[c] = lo[c].cwiseMin(positions[v]);
            hi[c] = hi[c].cwiseMax(positions[v]);
        }
    }
    size_t work = 0;
    for (size_t c = 0; c < nc; ++c)
    {
        if (!closed[c])
            continue;
        const Vec3& p = positions[probe[c]];
        for (size_t d = 0; d < nc; ++d)
        {
            if (d == c || !closed[d] || (p.array() < lo[d].array()).any() || (p.array() > hi[d].array()).any())
                continue;
            work += faces[d].size();
            if (work > max_solid_angles)
                return std::vector<uint32_t>(nc, 0);
            // The winding number of a closed surface is +-1 inside and 0 outside; 0.5 splits them.
            double omega = 0;
            for (const uint32_t f : faces[d])
                omega += solid_angle(positions[triangles[f][0]] - p, positions[triangles[f][1]] - p,
                                     positions[triangles[f][2]] - p);
            depth[c] += std::abs(omega) > 2 * std::numbers::pi;
        }
    }
    return depth;
}

} // namespace zomeify
