#include "core/surface/merge_overlaps.h"

#include <algorithm>
#include <limits>

#include <Eigen/Geometry>

#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/surface/edge_uses.h"
#include "core/surface/face_parts.h"
#include "core/surface/union_find.h"

namespace zomeify {

namespace {

using Triangle = std::array<uint32_t, 3>;
constexpr size_t max_parts = 1000; // a hostile file of many parts gets no merging, not a quadratic hang

struct Part
{
    std::vector<uint32_t> faces;
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
    double volume = 0.0; // signed, about the part's first vertex
};

bool boxes_meet(const Part& a, const Part& b)
{
    return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

bool box_holds(const Part& b, const Vec3& p)
{
    return (p.array() >= b.lo.array()).all() && (p.array() <= b.hi.array()).all();
}

TriangleMesh sub_mesh(const TriangleMesh& mesh, const std::vector<uint32_t>& faces)
{
    TriangleMesh out;
    std::vector<uint32_t> index(mesh.positions.size(), std::numeric_limits<uint32_t>::max());
    for (const uint32_t f : faces)
    {
        Triangle t = mesh.triangles[f];
        for (uint32_t& v : t)
        {
            if (index[v] == std::numeric_limits<uint32_t>::max())
            {
                index[v] = static_cast<uint32_t>(out.positions.size());
                out.positions.push_back(mesh.positions[v]);
            }
            v = index[v];
        }
        out.triangles.push_back(t);
    }
    return out;
}

Vec3 centroid(const TriangleMesh& m, uint32_t f)
{
    const Triangle& t = m.triangles[f];
    return (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0;
}

} // namespace

OverlapMerge merge_overlapping_parts(TriangleMesh& mesh)
{
    OverlapMerge out;
    size_t count = 0;
    const std::vector<uint32_t> part_of = face_parts(mesh.triangles, count);
    if (count < 2 || count > max_parts)
        return out;
    std::vector<Part> parts(count);
    for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
    {
        Part& p = parts[part_of[f]];
        const Triangle& t = mesh.triangles[f];
        const Vec3& o = mesh.positions[mesh.triangles[p.faces.empty() ? f : p.faces.front()][0]];
        p.faces.push_back(f);
        for (const uint32_t v : t)
        {
            p.lo = p.lo.cwiseMin(mesh.positions[v]);
            p.hi = p.hi.cwiseMax(mesh.positions[v]);
        }
        p.volume += (mesh.positions[t[0]] - o).dot((mesh.positions[t[1]] - o).cross(mesh.positions[t[2]] - o));
    }

    // Faces of part a inside part b, for every pair that overlaps: some of a's faces inside b, some
    // not (a part wholly inside another is nested, a cavity or a solid in a hollow, and stays).
    std::vector<uint8_t> remove(mesh.triangles.size(), 0);
    UnionFind group(count);
    std::vector<uint8_t> joined(count, 0);
    for (uint32_t b = 0; b < count; ++b)
    {
        if (parts[b].volume <= 0) // a cavity's shell faces inward: its inside is outside the solid
            continue;
        std::vector<uint32_t> partners;
        for (uint32_t a = 0; a < count; ++a)
            if (a != b && parts[a].volume > 0 && boxes_meet(parts[a], parts[b]))
                partners.push_back(a);
        if (partners.empty())
            continue;
        const SurfaceProjector projector(sub_mesh(mesh, parts[b].faces));
        const InsideTest inside(projector);
        std::vector<uint32_t> within;
        for (const uint32_t a : partners)
        {
            within.clear();
            for (const uint32_t f : parts[a].faces)
            {
                const Vec3 c = centroid(mesh, f);
                if (box_holds(parts[b], c) && inside.is_inside(c))
                    within.push_back(f);
            }
            if (within.empty() || within.size() == parts[a].faces.size())
                continue;
            for (const uint32_t f : within)
                remove[f] = 1;
            joined[a] = joined[b] = 1;
            group.unite(a, b);
        }
    }
    for (const uint8_t j : joined)
        out.joined_parts += j;
    if (!out.joined_parts)
        return out;

    size_t kept = 0;
    std::vector<uint8_t> group_kept(count, 0);
    for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
        if (!remove[f])
        {
            group_kept[group.find(part_of[f])] = 1;
            mesh.triangles[kept++] = mesh.triangles[f];
        }
        else
            ++out.removed_faces;
    mesh.triangles.resize(kept);
    drop_unused_vertices(mesh);
    for (const uint8_t g : group_kept)
        out.solids += g;

    // χ = V − E + F of what remains; each glued group is one closed surface of the union, so the
    // genus summed over them is (2 · groups − χ) / 2 (the crossing curves are circles, χ 0).
    const std::vector<EdgeUse> edges = sorted_edge_uses(mesh.triangles, mesh.positions.size());
    size_t unique = 0;
    for (size_t i = 0; i < edges.size();)
    {
        size_t j = i + 1;
        while (j < edges.size() && edges[j].key == edges[i].key)
            ++j;
        ++unique;
        out.seam_edges += j - i == 1;
        i = j;
    }
    const long long chi = static_cast<long long>(mesh.positions.size()) - static_cast<long long>(unique) +
                          static_cast<long long>(mesh.triangles.size());
    out.genus = (2 * static_cast<long long>(out.solids) - chi) / 2;
    return out;
}

} // namespace zomeify
