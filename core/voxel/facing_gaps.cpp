#include "core/voxel/facing_gaps.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace zomeify {

double FacingGaps::fraction_narrower_than(double width) const
{
    if (widths.empty())
        return 0.0;
    const auto narrow = std::count_if(widths.begin(), widths.end(), [&](double w) { return w >= 0.0 && w < width; });
    return static_cast<double>(narrow) / static_cast<double>(widths.size());
}

FacingGaps facing_gaps(const SurfaceProjector& surface, double max_width, int samples)
{
    FacingGaps out;
    const TriangleMesh& mesh = surface.mesh();
    if (mesh.triangles.empty() || samples <= 0 || !(max_width > 0.0))
        return out;
    std::vector<double> cumulative(mesh.triangles.size());
    double total = 0.0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
    {
        const auto& tri = mesh.triangles[t];
        const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &c = mesh.positions[tri[2]];
        total += 0.5 * (b - a).cross(c - a).norm();
        cumulative[t] = total;
    }
    if (!(total > 0.0))
        return out;
    std::mt19937_64 random(12345);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    constexpr int kSteps = 24;
    const double step = 0.5 * max_width / kSteps; // parts facing across a gap w meet halfway, at w / 2
    out.widths.reserve(static_cast<size_t>(samples));
    for (int s = 0; s < samples; ++s)
    {
        const double pick = unit(random) * total;
        const size_t t = std::min(
            mesh.triangles.size() - 1,
            static_cast<size_t>(std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()));
        double u = unit(random), v = unit(random);
        if (u + v > 1.0)
        {
            u = 1.0 - u;
            v = 1.0 - v;
        }
        const auto& tri = mesh.triangles[t];
        const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &c = mesh.positions[tri[2]];
        const Vec3 p = a + u * (b - a) + v * (c - a);
        const Vec3 n = surface.face_normals()[t];
        double width = -1.0;
        for (int k = 1; k <= kSteps; ++k)
        {
            const double along = k * step;
            const Vec3 q = p + along * n;
            const ClosestPoint other = surface.project(q);
            const double d = std::sqrt(other.distance_squared);
            if (d < 0.9 * along && other.normal.dot(n) < -0.5)
            {
                width = (other.point - p).norm();
                break;
            }
        }
        out.widths.push_back(width <= max_width ? width : -1.0);
    }
    return out;
}

} // namespace zomeify
