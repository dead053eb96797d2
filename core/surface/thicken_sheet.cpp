#include "core/surface/thicken_sheet.h"

#include <algorithm>
#include <limits>

#include <Eigen/Geometry>

#include "core/surface/edge_uses.h"

namespace zomeify {

namespace {

using Triangle = std::array<uint32_t, 3>;
constexpr uint32_t none = std::numeric_limits<uint32_t>::max();

} // namespace

double thicken_sheets(TriangleMesh& mesh, const std::vector<uint8_t>& sheet_face)
{
    std::vector<Triangle> sheet, kept;
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        (sheet_face[f] ? sheet : kept).push_back(mesh.triangles[f]);
    if (sheet.empty())
        return 0.0;

    // Thickness from the sheets' own box; normals weighted by area, so a sliver tips nothing.
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    std::vector<Vec3> normal(mesh.positions.size(), Vec3::Zero());
    for (const Triangle& t : sheet)
    {
        const Vec3 n = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
        for (const uint32_t v : t)
        {
            normal[v] += n;
            lo = lo.cwiseMin(mesh.positions[v]);
            hi = hi.cwiseMax(mesh.positions[v]);
        }
    }
    const double thickness = kSheetThicknessFraction * (hi - lo).maxCoeff();

    // Each sheet vertex becomes two: above (+n) and below (−n).
    std::vector<Vec3> positions;
    std::vector<uint32_t> above(mesh.positions.size(), none), below(mesh.positions.size(), none);
    for (const Triangle& t : kept)
        for (const uint32_t v : t)
            if (above[v] == none)
            {
                above[v] = below[v] = static_cast<uint32_t>(positions.size());
                positions.push_back(mesh.positions[v]);
            }
    for (const Triangle& t : sheet)
        for (const uint32_t v : t)
            if (above[v] == none)
            {
                const double length = normal[v].norm();
                const Vec3 offset = length > 0 ? Vec3(normal[v] * (0.5 * thickness / length)) : Vec3(Vec3::Zero());
                above[v] = static_cast<uint32_t>(positions.size());
                positions.push_back(mesh.positions[v] + offset);
                below[v] = static_cast<uint32_t>(positions.size());
                positions.push_back(mesh.positions[v] - offset);
            }

    std::vector<Triangle> triangles;
    triangles.reserve(kept.size() + 2 * sheet.size());
    for (const Triangle& t : kept)
        triangles.push_back({above[t[0]], above[t[1]], above[t[2]]});
    for (const Triangle& t : sheet)
    {
        triangles.push_back({above[t[0]], above[t[1]], above[t[2]]});
        triangles.push_back({below[t[0]], below[t[2]], below[t[1]]});
    }
    // The wall along the open edge: where the top runs u → v, the wall runs v → u on top and
    // u → v below, closing both sides.
    const std::vector<EdgeUse> uses = sorted_edge_uses(sheet, mesh.positions.size());
    for (size_t i = 0; i < uses.size();)
    {
        size_t j = i + 1;
        while (j < uses.size() && uses[j].key == uses[i].key)
            ++j;
        if (j - i == 1)
        {
            const Triangle& t = sheet[uses[i].face];
            const uint32_t u = t[uses[i].corner], v = t[(uses[i].corner + 1) % 3];
            triangles.push_back({above[v], above[u], below[u]});
            triangles.push_back({above[v], below[u], below[v]});
        }
        i = j;
    }
    mesh.positions = std::move(positions);
    mesh.triangles = std::move(triangles);
    return thickness;
}

} // namespace zomeify
