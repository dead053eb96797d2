#include "core/anneal/energy/face_shape.h"

#include <algorithm>
#include <cmath>

#include "core/geom/point_triangle.h"
#include "core/mesh/face_triangles.h"

namespace zomeify {
namespace {

Vec3 to_vec3(const ZVec& p)
{
    const auto c = p.to_double();
    return {c[0], c[1], c[2]};
}

} // namespace

FaceShape face_shape(std::span<const ZVec> corners) noexcept
{
    FaceShape s;
    const FaceTriangles t = face_triangles(corners);
    s.count = t.count;
    for (int i = 0; i < t.count; ++i)
    {
        for (int k = 0; k < 3; ++k)
        {
            s.triangles[i][k] = to_vec3(t.triangles[i][k]);
            s.box.extend(s.triangles[i][k]);
        }
        const Vec3 n = (s.triangles[i][1] - s.triangles[i][0]).cross(s.triangles[i][2] - s.triangles[i][0]);
        const double length = n.norm();
        s.normals[i] = length > 1e-9 ? Vec3(n / length) : Vec3::Zero();
    }
    return s;
}

double face_distance_squared(const Vec3& p, const FaceShape& face) noexcept
{
    double best = point_triangle_distance_squared(p, face.triangles[0][0], face.triangles[0][1], face.triangles[0][2]);
    if (face.count == 2)
        best = std::min(
            best, point_triangle_distance_squared(p, face.triangles[1][0], face.triangles[1][1], face.triangles[1][2]));
    return best;
}

double face_distance_squared_below(const Vec3& p, const FaceShape& face, double bound) noexcept
{
    // Both tests are lower bounds of the true distance; the slack absorbs their rounding.
    constexpr double kSlack = 1e-9;
    const double limit = bound + kSlack;
    const double box = face.box.distance_squared(p);
    if (box > limit)
        return box;
    double best = limit;
    for (int i = 0; i < face.count; ++i)
    {
        const auto& t = face.triangles[i];
        const double plane = face.normals[i].dot(p - t[0]);
        if (plane * plane > best + kSlack)
            continue;
        best = std::min(best, point_triangle_distance_squared(p, t[0], t[1], t[2]));
    }
    return best;
}

} // namespace zomeify
