#include "tests/support/geom_fixtures.h"

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <Eigen/Geometry>

namespace zomeify::test {
namespace {

using Tri = std::array<uint32_t, 3>;

TriangleMesh translated(TriangleMesh mesh, const Vec3& offset)
{
    for (Vec3& p : mesh.positions)
    {
        p += offset;
    }
    return mesh;
}

} // namespace

TriangleMesh make_uv_sphere(double radius, int rings, int segments)
{
    TriangleMesh m;
    const double pi = std::numbers::pi;
    m.positions.push_back(Vec3(0, 0, radius)); // north pole
    for (int i = 1; i < rings; ++i)
    {
        const double theta = pi * i / rings;
        for (int j = 0; j < segments; ++j)
        {
            const double phi = 2 * pi * j / segments;
            m.positions.push_back(
                radius * Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)));
        }
    }
    const auto south = static_cast<uint32_t>(m.positions.size());
    m.positions.push_back(Vec3(0, 0, -radius));
    auto ring = [&](int i, int j) { return static_cast<uint32_t>(1 + (i - 1) * segments + (j % segments)); };
    for (int j = 0; j < segments; ++j)
    {
        m.triangles.push_back(Tri{0, ring(1, j), ring(1, j + 1)});
        m.triangles.push_back(Tri{south, ring(rings - 1, j + 1), ring(rings - 1, j)});
    }
    for (int i = 1; i + 1 < rings; ++i)
    {
        for (int j = 0; j < segments; ++j)
        {
            m.triangles.push_back(Tri{ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            m.triangles.push_back(Tri{ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
    }
    return m;
}

TriangleMesh make_icosphere(double radius, int levels)
{
    const double t = std::numbers::phi;
    TriangleMesh m;
    m.positions = {Vec3(-1, t, 0),  Vec3(1, t, 0),  Vec3(-1, -t, 0), Vec3(1, -t, 0), Vec3(0, -1, t),  Vec3(0, 1, t),
                   Vec3(0, -1, -t), Vec3(0, 1, -t), Vec3(t, 0, -1),  Vec3(t, 0, 1),  Vec3(-t, 0, -1), Vec3(-t, 0, 1)};
    m.triangles = {Tri{0, 11, 5}, Tri{0, 5, 1},  Tri{0, 1, 7},   Tri{0, 7, 10}, Tri{0, 10, 11},
                   Tri{1, 5, 9},  Tri{5, 11, 4}, Tri{11, 10, 2}, Tri{10, 7, 6}, Tri{7, 1, 8},
                   Tri{3, 9, 4},  Tri{3, 4, 2},  Tri{3, 2, 6},   Tri{3, 6, 8},  Tri{3, 8, 9},
                   Tri{4, 9, 5},  Tri{2, 4, 11}, Tri{6, 2, 10},  Tri{8, 6, 7},  Tri{9, 8, 1}};
    for (int level = 0; level < levels; ++level)
    {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto [it, added] = midpoints.try_emplace(key, static_cast<uint32_t>(m.positions.size()));
            if (added)
            {
                m.positions.push_back(0.5 * (m.positions[a] + m.positions[b]));
            }
            return it->second;
        };
        std::vector<Tri> next;
        for (const Tri& f : m.triangles)
        {
            const uint32_t ab = midpoint(f[0], f[1]);
            const uint32_t bc = midpoint(f[1], f[2]);
            const uint32_t ca = midpoint(f[2], f[0]);
            next.push_back(Tri{f[0], ab, ca});
            next.push_back(Tri{f[1], bc, ab});
            next.push_back(Tri{f[2], ca, bc});
            next.push_back(Tri{ab, bc, ca});
        }
        m.triangles = std::move(next);
    }
    for (Vec3& p : m.positions)
    {
        p = radius * p.normalized();
    }
    return m;
}

TriangleMesh make_torus(double major, double minor, int major_segments, int minor_segments)
{
    TriangleMesh m;
    const double pi = std::numbers::pi;
    for (int i = 0; i < major_segments; ++i)
    {
        const double u = 2 * pi * i / major_segments;
        const Vec3 radial(std::cos(u), 0, std::sin(u));
        for (int j = 0; j < minor_segments; ++j)
        {
            const double v = 2 * pi * j / minor_segments;
            m.positions.push_back((major + minor * std::cos(v)) * radial + Vec3(0, minor * std::sin(v), 0));
        }
    }
    auto index = [&](int i, int j) {
        return static_cast<uint32_t>((i % major_segments) * minor_segments + (j % minor_segments));
    };
    // With u turning from +x towards +z and v from outward towards +y, the tube's outward normal is
    // d/dv x d/du, so (i, j) -> (i, j+1) -> (i+1, j) is counter-clockwise seen from outside.
    for (int i = 0; i < major_segments; ++i)
    {
        for (int j = 0; j < minor_segments; ++j)
        {
            m.triangles.push_back(Tri{index(i, j), index(i, j + 1), index(i + 1, j + 1)});
            m.triangles.push_back(Tri{index(i, j), index(i + 1, j + 1), index(i + 1, j)});
        }
    }
    return m;
}

TriangleMesh make_cube(double half, int n)
{
    TriangleMesh m;
    std::map<std::array<int, 3>, uint32_t> ids;
    auto vertex = [&](const std::array<int, 3>& g) {
        auto [it, added] = ids.try_emplace(g, static_cast<uint32_t>(m.positions.size()));
        if (added)
        {
            m.positions.push_back(Vec3(g[0], g[1], g[2]) * (2.0 * half / n) - Vec3::Constant(half));
        }
        return it->second;
    };
    // For each axis and side, (u, v) span the face so that u x v points outward.
    for (int axis = 0; axis < 3; ++axis)
    {
        for (int side = 0; side < 2; ++side)
        {
            int u = (axis + 1) % 3;
            int v = (axis + 2) % 3;
            if (side == 0)
            {
                std::swap(u, v);
            }
            for (int a = 0; a < n; ++a)
            {
                for (int b = 0; b < n; ++b)
                {
                    auto corner = [&](int da, int db) {
                        std::array<int, 3> g{};
                        g[axis] = side * n;
                        g[u] = a + da;
                        g[v] = b + db;
                        return vertex(g);
                    };
                    m.triangles.push_back(Tri{corner(0, 0), corner(1, 0), corner(1, 1)});
                    m.triangles.push_back(Tri{corner(0, 0), corner(1, 1), corner(0, 1)});
                }
            }
        }
    }
    return m;
}

std::vector<NamedMesh> procedural_surfaces()
{
    std::vector<NamedMesh> out;
    out.push_back({"uv_sphere", translated(make_uv_sphere(1.5, 24, 48), Vec3(0.3, -0.2, 0.1))});
    out.push_back({"icosphere", translated(make_icosphere(2.0, 3), Vec3(10.0, 5.0, -3.0))});
    out.push_back({"torus", translated(make_torus(1.0, 0.3, 48, 24), Vec3(-0.5, 0.25, 2.0))});
    out.push_back({"cube", translated(make_cube(1.0, 4), Vec3(0.1, 0.2, 0.3))});
    return out;
}

} // namespace zomeify::test
