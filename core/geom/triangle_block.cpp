#include "core/geom/triangle_block.h"

#include "core/geom/triangle_estimate.h"

#include <algorithm>
#include <cstring>

#include <Eigen/Geometry>

namespace zomeify {

TriangleBlock make_triangle_block(const TriangleMesh& mesh, const uint32_t* ids, uint32_t count, const Vec3& origin,
                                  double sliver_width)
{
    TriangleBlock block{};
    for (int lane = 0; lane < 4; ++lane)
    {
        const auto& tri = mesh.triangles[ids[lane < static_cast<int>(count) ? lane : 0]];
        const Vec3& a = mesh.positions[tri[0]];
        const Vec3 ab = mesh.positions[tri[1]] - a;
        const Vec3 ac = mesh.positions[tri[2]] - a;
        const Vec3 cross = ab.cross(ac);
        const double longest = std::max({ab.norm(), ac.norm(), (ac - ab).norm()});
        const double area2 = cross.norm();
        // Width = 2 · area / longest edge. Below the threshold the double cross product may have
        // lost its direction to cancellation; the block then measures to the edges only.
        const Vec3 normal = area2 > sliver_width * longest && area2 > 0.0 ? Vec3(cross / area2) : Vec3::Zero();
        const Vec3 rel = a - origin;
        block.ax[lane] = static_cast<float>(rel.x());
        block.ay[lane] = static_cast<float>(rel.y());
        block.az[lane] = static_cast<float>(rel.z());
        block.abx[lane] = static_cast<float>(ab.x());
        block.aby[lane] = static_cast<float>(ab.y());
        block.abz[lane] = static_cast<float>(ab.z());
        block.acx[lane] = static_cast<float>(ac.x());
        block.acy[lane] = static_cast<float>(ac.y());
        block.acz[lane] = static_cast<float>(ac.z());
        block.nx[lane] = static_cast<float>(normal.x());
        block.ny[lane] = static_cast<float>(normal.y());
        block.nz[lane] = static_cast<float>(normal.z());
    }
    return block;
}

std::array<float, 4> estimate_block_distances_squared(const TriangleBlock& block, const Vec3& p_relative,
                                                      double magnitude)
{
    const double margin = TriangleBlockTolerance::kInsideMargin * magnitude;
    const simd::F4 estimate = estimate_distances_squared(
        block, simd::splat(static_cast<float>(p_relative.x())), simd::splat(static_cast<float>(p_relative.y())),
        simd::splat(static_cast<float>(p_relative.z())), simd::splat(static_cast<float>(margin * margin)));
    std::array<float, 4> out{};
    std::memcpy(out.data(), &estimate, sizeof(estimate));
    return out;
}

} // namespace zomeify
