#include "core/surface/triangulate.h"

#include <Eigen/Geometry>

namespace zomeify {

namespace {

using Vec2 = Eigen::Vector2d;

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

void fan(std::span<const uint32_t> polygon, std::vector<std::array<uint32_t, 3>>& out)
{
    for (size_t i = 1; i + 1 < polygon.size(); ++i)
        out.push_back({polygon[0], polygon[i], polygon[i + 1]});
}

// Strictly inside or on the edges of the counter-clockwise triangle abc.
bool in_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c)
{
    return cross2(b - a, p - a) >= 0 && cross2(c - b, p - b) >= 0 && cross2(a - c, p - c) >= 0;
}

// Ear clipping on a counter-clockwise simple polygon. False if no ear is found (the polygon is
// not simple) or the work exceeds 4 n^2 point tests (a hostile polygon could otherwise cost n^3),
// in which case `out` is left as it was.
bool ear_clip(std::span<const uint32_t> polygon, const std::vector<Vec2>& pts,
              std::vector<std::array<uint32_t, 3>>& out)
{
    std::vector<size_t> ring(polygon.size());
    for (size_t i = 0; i < ring.size(); ++i)
        ring[i] = i;
    std::vector<std::array<uint32_t, 3>> triangles;
    size_t budget = 4 * polygon.size() * polygon.size();
    while (ring.size() > 3)
    {
        const size_t n = ring.size();
        bool clipped = false;
        for (size_t i = 0; i < n && !clipped; ++i)
        {
            const size_t ia = ring[(i + n - 1) % n], ib = ring[i], ic = ring[(i + 1) % n];
            const Vec2 &a = pts[ia], &b = pts[ib], &c = pts[ic];
            if (cross2(b - a, c - b) <= 0)
                continue; // reflex or flat corner: not an ear
            bool empty = true;
            for (size_t j = 0; j < n && empty; ++j)
            {
                const size_t k = ring[j];
                if (k == ia || k == ib || k == ic)
                    continue;
                if (budget-- == 0)
                    return false;
                empty = !in_triangle(pts[k], a, b, c);
            }
            if (!empty)
                continue;
            triangles.push_back({polygon[ia], polygon[ib], polygon[ic]});
            ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
            clipped = true;
        }
        if (!clipped)
            return false;
    }
    triangles.push_back({polygon[ring[0]], polygon[ring[1]], polygon[ring[2]]});
    out.insert(out.end(), triangles.begin(), triangles.end());
    return true;
}

} // namespace

void triangulate_polygon(const std::vector<Vec3>& positions, std::span<const uint32_t> polygon,
                         std::vector<std::array<uint32_t, 3>>& out)
{
    const size_t n = polygon.size();
    if (n == 3)
    {
        out.push_back({polygon[0], polygon[1], polygon[2]});
        return;
    }
    // Newell's normal: the polygon's area vector, robust for non-planar and non-convex polygons.
    Vec3 normal = Vec3::Zero();
    for (size_t i = 0; i < n; ++i)
        normal += positions[polygon[i]].cross(positions[polygon[(i + 1) % n]]);
    if (!(normal.squaredNorm() > 0))
    {
        fan(polygon, out);
        return;
    }
    normal.normalize();
    // A basis (u, v) of the plane with u x v = normal, so the polygon runs counter-clockwise in it.
    const Vec3 u = normal.unitOrthogonal();
    const Vec3 v = normal.cross(u);
    std::vector<Vec2> pts(n);
    for (size_t i = 0; i < n; ++i)
        pts[i] = Vec2(positions[polygon[i]].dot(u), positions[polygon[i]].dot(v));

    bool convex = true;
    for (size_t i = 0; i < n && convex; ++i)
        convex = cross2(pts[(i + 1) % n] - pts[i], pts[(i + 2) % n] - pts[(i + 1) % n]) >= 0;
    constexpr size_t max_ear_clip = 256; // ear clipping is O(n^3) in the worst case
    if (convex || n > max_ear_clip || !ear_clip(polygon, pts, out))
        fan(polygon, out);
}

} // namespace zomeify
