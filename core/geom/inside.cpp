#include "core/geom/inside.h"

#include <cmath>
#include <unordered_map>

namespace zomeify {

InsideTest::InsideTest(const SurfaceProjector& projector) : projector_(projector)
{
    // Each undirected edge collects the unit normals of its faces. On a 2-manifold that is
    // exactly two faces with equal angle weights (pi each), so the sum is the pseudo-normal.
    const TriangleMesh& mesh = projector.mesh();
    const std::vector<Vec3>& face_normals = projector.face_normals();
    std::unordered_map<uint64_t, Vec3> edge_sum;
    edge_sum.reserve(mesh.triangles.size() * 2);
    auto key = [](uint32_t a, uint32_t b) { return a < b ? (uint64_t{a} << 32) | b : (uint64_t{b} << 32) | a; };
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
    {
        const auto& tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k)
        {
            auto [it, added] = edge_sum.try_emplace(key(tri[k], tri[(k + 1) % 3]), Vec3::Zero());
            it->second += face_normals[t];
        }
    }
    edge_normals_.resize(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
    {
        const auto& tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k)
        {
            edge_normals_[t][k] = edge_sum.at(key(tri[k], tri[(k + 1) % 3]));
        }
    }
}

Vec3 InsideTest::pseudo_normal(uint32_t t, TriangleFeature feature) const
{
    const auto& tri = projector_.mesh().triangles[t];
    const std::vector<Vec3>& vertex_normals = projector_.vertex_normals();
    switch (feature)
    {
    case TriangleFeature::face:
        return projector_.face_normals()[t];
    case TriangleFeature::edge01:
        return edge_normals_[t][0];
    case TriangleFeature::edge12:
        return edge_normals_[t][1];
    case TriangleFeature::edge20:
        return edge_normals_[t][2];
    case TriangleFeature::vertex0:
        return vertex_normals[tri[0]];
    case TriangleFeature::vertex1:
        return vertex_normals[tri[1]];
    case TriangleFeature::vertex2:
        return vertex_normals[tri[2]];
    }
    return projector_.face_normals()[t];
}

bool InsideTest::is_inside(const Vec3& p) const { return is_inside(p, projector_.project(p)); }

bool InsideTest::is_inside(const Vec3& p, const ClosestPoint& closest) const
{
    return (p - closest.point).dot(pseudo_normal(closest.triangle, closest.feature)) < 0.0;
}

double InsideTest::signed_distance(const Vec3& p) const
{
    const ClosestPoint closest = projector_.project(p);
    const double d = std::sqrt(closest.distance_squared);
    return is_inside(p, closest) ? -d : d;
}

} // namespace zomeify
