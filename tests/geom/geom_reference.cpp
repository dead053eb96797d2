#include "tests/geom/geom_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace zomeify::test {
namespace {

double segment_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    double t = len2 > 0 ? (p - a).dot(ab) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return (p - (a + t * ab)).squaredNorm();
}

// Moller-Trumbore; counts a crossing for t > 0 only.
bool ray_hits(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 e1 = b - a;
    const Vec3 e2 = c - a;
    const Vec3 h = d.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-300)
    {
        return false;
    }
    const double inv = 1.0 / det;
    const Vec3 s = o - a;
    const double u = inv * s.dot(h);
    if (u < 0.0 || u > 1.0)
    {
        return false;
    }
    const Vec3 q = s.cross(e1);
    const double v = inv * d.dot(q);
    if (v < 0.0 || u + v > 1.0)
    {
        return false;
    }
    return inv * e2.dot(q) > 0.0;
}

} // namespace

double reference_triangle_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    double best = std::min(
        {segment_distance_squared(p, a, b), segment_distance_squared(p, b, c), segment_distance_squared(p, c, a)});
    const Vec3 n = (b - a).cross(c - a);
    const double n2 = n.squaredNorm();
    if (n2 > 0)
    {
        const Vec3 q = p - ((p - a).dot(n) / n2) * n;
        const bool inside =
            (b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 && (a - c).cross(q - c).dot(n) >= 0;
        if (inside)
        {
            best = std::min(best, (p - q).squaredNorm());
        }
    }
    return best;
}

double brute_force_distance_squared(const TriangleMesh& mesh, const Vec3& p)
{
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles)
    {
        best = std::min(best, reference_triangle_distance_squared(p, mesh.positions[t[0]], mesh.positions[t[1]],
                                                                  mesh.positions[t[2]]));
    }
    return best;
}

bool ray_parity_inside(const TriangleMesh& mesh, const Vec3& p, int rays, uint32_t seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    int inside_votes = 0;
    for (int r = 0; r < rays; ++r)
    {
        const Vec3 d = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
        int crossings = 0;
        for (const auto& t : mesh.triangles)
        {
            crossings += ray_hits(p, d, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]) ? 1 : 0;
        }
        inside_votes += crossings % 2;
    }
    return 2 * inside_votes > rays;
}

double bbox_diagonal(const TriangleMesh& mesh)
{
    Vec3 lo = mesh.positions.front();
    Vec3 hi = lo;
    for (const Vec3& p : mesh.positions)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return (hi - lo).norm();
}

Vec3 random_point_in_box(const TriangleMesh& mesh, double margin, std::mt19937& rng)
{
    Vec3 lo = mesh.positions.front();
    Vec3 hi = lo;
    for (const Vec3& p : mesh.positions)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const double grow = margin * (hi - lo).norm();
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Vec3 out;
    for (int k = 0; k < 3; ++k)
    {
        out[k] = lo[k] - grow + u(rng) * (hi[k] - lo[k] + 2 * grow);
    }
    return out;
}

Vec3 random_point_near_surface(const TriangleMesh& mesh, double radius, std::mt19937& rng)
{
    std::vector<double> areas;
    areas.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
    {
        const Vec3& a = mesh.positions[t[0]];
        areas.push_back((mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a).norm());
    }
    std::discrete_distribution<size_t> pick(areas.begin(), areas.end());
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    const auto& t = mesh.triangles[pick(rng)];
    double s = u(rng);
    double r = u(rng);
    if (s + r > 1.0)
    {
        s = 1.0 - s;
        r = 1.0 - r;
    }
    const Vec3& a = mesh.positions[t[0]];
    const Vec3 on = a + s * (mesh.positions[t[1]] - a) + r * (mesh.positions[t[2]] - a);
    const Vec3 dir = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    return on + radius * std::cbrt(u(rng)) * dir;
}

double signed_volume(const TriangleMesh& mesh)
{
    double v = 0.0;
    for (const auto& t : mesh.triangles)
    {
        v += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]])) / 6.0;
    }
    return v;
}

std::vector<std::string> shared_mesh_names()
{
    return {"3holes.obj",    "bunny.obj",     "cube.obj",     "eight.obj",  "elk.obj",
            "fertility.obj", "rockerarm.obj", "scorpion.obj", "sphere.obj", "torus.obj"};
}

std::string shared_mesh_path(const std::string& name) { return std::string(ZOME_SHARED_DIR) + "/data/meshes/" + name; }

} // namespace zomeify::test
