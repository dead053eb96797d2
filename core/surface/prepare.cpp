#include "core/surface/prepare.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "core/base/errors.h"
#include "core/surface/close_surface.h"
#include "core/surface/merge_overlaps.h"
#include "core/surface/read_mesh.h"
#include "core/surface/topology.h"
#include "core/surface/triangulate.h"
#include "core/surface/weld.h"

namespace zomeify {

namespace {

using Triangle = std::array<uint32_t, 3>;

std::string plural(size_t n, const std::string& one, const std::string& many)
{
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string pair_text(const std::array<uint32_t, 2>& e)
{
    return "between vertices " + std::to_string(e[0]) + " and " + std::to_string(e[1]);
}

// The polygon mapped through the weld, with cyclically repeated neighbours removed (an edge the
// weld collapsed). Empty if what remains is not a simple polygon (fewer than 3 corners, or a
// vertex used twice).
std::vector<uint32_t> welded_polygon(const std::vector<uint32_t>& polygon, const std::vector<uint32_t>& target)
{
    std::vector<uint32_t> out;
    out.reserve(polygon.size());
    for (const uint32_t i : polygon)
        if (out.empty() || out.back() != target[i])
            out.push_back(target[i]);
    while (out.size() > 1 && out.front() == out.back())
        out.pop_back();
    if (out.size() < 3)
        return {};
    std::vector<uint32_t> sorted = out;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        return {};
    return out;
}

// The same triangle up to rotation: smallest index first, orientation kept.
Triangle canonical(const Triangle& t)
{
    const int m = t[0] < t[1] ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
    return {t[m], t[(m + 1) % 3], t[(m + 2) % 3]};
}

void describe_repairs(SurfaceReport& r)
{
    if (r.welded_vertices)
        r.repairs.push_back("welded " + plural(r.welded_vertices, "duplicate vertex", "duplicate vertices"));
    if (r.unreferenced_vertices)
        r.repairs.push_back("removed " + plural(r.unreferenced_vertices, "unused vertex", "unused vertices"));
    if (r.dropped_small_faces)
        r.repairs.push_back("dropped " + plural(r.dropped_small_faces, "face", "faces") +
                            " with fewer than 3 vertices");
    if (r.dropped_invalid_faces)
        r.repairs.push_back("dropped " + plural(r.dropped_invalid_faces, "face", "faces") +
                            " with an index out of range or a NaN/infinite vertex");
    if (r.dropped_degenerate_faces)
        r.repairs.push_back("dropped " + plural(r.dropped_degenerate_faces, "degenerate face", "degenerate faces") +
                            " (repeated vertex or zero area)");
    if (r.dropped_duplicate_faces)
        r.repairs.push_back("dropped " + plural(r.dropped_duplicate_faces, "duplicate face", "duplicate faces"));
    if (r.triangulated_polygons)
        r.repairs.push_back("triangulated " + plural(r.triangulated_polygons, "polygon", "polygons"));
    if (r.flipped_faces)
        r.repairs.push_back("flipped " + plural(r.flipped_faces, "face", "faces") +
                            " to orient every component consistently and outward" +
                            (r.cavities ? " (cavities inward)" : ""));
}

void describe_problems(SurfaceReport& r, const TopologyInfo& t, const std::vector<uint32_t>& original,
                       const SurfaceClosing& closing)
{
    if (r.faces == 0)
    {
        r.problems.push_back(r.input_faces == 0
                                 ? "mesh has no faces"
                                 : "mesh has no usable faces (all " + std::to_string(r.input_faces) + " were dropped)");
        return;
    }
    const auto in = [&](uint32_t v) { return original[v]; };
    if (r.dropped_invalid_faces)
        r.problems.push_back(plural(r.dropped_invalid_faces, "face uses", "faces use") +
                             " an index out of range or a NaN/infinite vertex; fix the file's indices and coordinates");
    if (closing.only_sheets)
    {
        // Its edges and holes are the sheet's own: the one reason is that it has no inside.
        r.problems.push_back(
            "mesh is an open sheet, not a solid: its open edge (" +
            plural(closing.sheet_boundary_edges, "boundary edge", "boundary edges") +
            ") runs around it, and closing "
            "it would add " +
            std::to_string(static_cast<int>(std::lround(100 * closing.sheet_patch_ratio))) +
            "% of its area; give it a thickness (--thicken; on the page, 'Give it a thickness') or close it in "
            "a modeller first");
        return;
    }
    if (t.non_manifold_edges)
        r.problems.push_back("mesh is not manifold: " + plural(t.non_manifold_edges, "edge is", "edges are") +
                             " shared by more than two faces (e.g. " +
                             pair_text({in(t.non_manifold_edge_example[0]), in(t.non_manifold_edge_example[1])}) +
                             "); separate the parts that meet there");
    else if (t.non_manifold_vertices)
        r.problems.push_back(
            "mesh is not manifold: " + plural(t.non_manifold_vertices, "vertex joins", "vertices join") +
            " separate fans of faces (e.g. vertex " + std::to_string(in(t.non_manifold_vertex_example)) +
            "); separate the parts that touch there");
    if (t.non_orientable_components)
        r.problems.push_back(plural(t.non_orientable_components, "component cannot", "components cannot") +
                             " be oriented consistently (one-sided surface)");
    if (t.boundary_edges)
        r.problems.push_back("mesh is not closed: " + plural(t.holes, "hole", "holes") + " (" +
                             plural(t.boundary_edges, "boundary edge", "boundary edges") + ", e.g. " +
                             pair_text({in(t.boundary_example[0]), in(t.boundary_example[1])}) + "); fill the " +
                             plural(t.holes, "hole", "holes") + " first");
}

PreparedSurface run(const PolygonSoup& soup, const PrepareOptions& options)
{
    PreparedSurface out;
    SurfaceReport& r = out.report;
    const size_t nv = soup.positions.size();
    r.input_vertices = nv;
    r.input_faces = soup.polygons.size();

    // Usable faces: at least 3 corners, every index in range and every corner finite.
    std::vector<bool> non_finite(nv, false);
    for (size_t i = 0; i < nv; ++i)
        if (!soup.positions[i].allFinite())
        {
            non_finite[i] = true;
            ++r.non_finite_vertices;
        }
    std::vector<uint8_t> usable(soup.polygons.size(), 0);
    std::vector<bool> referenced(nv, false);
    for (size_t f = 0; f < soup.polygons.size(); ++f)
    {
        const auto& polygon = soup.polygons[f];
        if (polygon.size() < 3)
        {
            ++r.dropped_small_faces;
            continue;
        }
        const bool valid =
            std::all_of(polygon.begin(), polygon.end(), [&](uint32_t i) { return i < nv && !non_finite[i]; });
        if (!valid)
        {
            ++r.dropped_invalid_faces;
            continue;
        }
        usable[f] = 1;
        for (const uint32_t i : polygon)
            referenced[i] = true;
    }

    // The bounding box of what the faces use sets the scale of every tolerance, so a stray
    // unused vertex far away cannot make the weld swallow real detail.
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = -lo;
    for (size_t i = 0; i < nv; ++i)
        if (referenced[i])
        {
            lo = lo.cwiseMin(soup.positions[i]);
            hi = hi.cwiseMax(soup.positions[i]);
        }
    const bool any = lo.x() <= hi.x();
    // Coordinates near the double range overflow the diagonal; relative tolerances are then
    // meaningless (an infinite one would weld everything), so only exact duplicates are welded.
    const double raw_diagonal = any ? (hi - lo).norm() : 0.0;
    const bool huge = !std::isfinite(raw_diagonal);
    const double diagonal = huge ? 0.0 : raw_diagonal;
    if (any)
        for (int a = 0; a < 3; ++a)
        {
            r.bbox_min[a] = lo[a];
            r.bbox_max[a] = hi[a];
        }

    std::vector<bool> skip(nv);
    for (size_t i = 0; i < nv; ++i)
        skip[i] = !referenced[i];
    const std::vector<uint32_t> target = weld_vertices(soup.positions, options.weld_tolerance * diagonal, skip);
    for (size_t i = 0; i < nv; ++i)
        r.welded_vertices += referenced[i] && target[i] != i;

    // Polygons to triangles over welded indices (still indexing soup.positions).
    std::vector<Triangle> triangles;
    triangles.reserve(soup.polygons.size());
    const double min_double_area = 2 * options.degenerate_area * diagonal * diagonal;
    for (size_t f = 0; f < soup.polygons.size(); ++f)
    {
        if (!usable[f])
            continue;
        const std::vector<uint32_t> polygon = welded_polygon(soup.polygons[f], target);
        if (polygon.empty())
        {
            ++r.dropped_degenerate_faces;
            continue;
        }
        const size_t before = triangles.size();
        triangulate_polygon(soup.positions, polygon, triangles);
        r.triangulated_polygons += polygon.size() > 3;
        // Zero-area triangles (also those a fan makes of a polygon with collinear corners).
        size_t kept = before;
        for (size_t t = before; t < triangles.size(); ++t)
        {
            const Triangle& tri = triangles[t];
            const Vec3& p = soup.positions[tri[0]];
            const double twice_area = (soup.positions[tri[1]] - p).cross(soup.positions[tri[2]] - p).norm();
            if (twice_area <= min_double_area)
                ++r.dropped_degenerate_faces;
            else
                triangles[kept++] = tri;
        }
        triangles.resize(kept);
    }

    // Exact duplicates with the same orientation (STL exports and merged files repeat faces).
    {
        std::vector<std::pair<Triangle, uint32_t>> keyed(triangles.size());
        for (uint32_t t = 0; t < triangles.size(); ++t)
            keyed[t] = {canonical(triangles[t]), t};
        std::sort(keyed.begin(), keyed.end());
        std::vector<uint8_t> drop(triangles.size(), 0);
        for (size_t i = 1; i < keyed.size(); ++i)
            if (keyed[i].first == keyed[i - 1].first)
                drop[keyed[i].second] = 1;
        size_t kept = 0;
        for (size_t t = 0; t < triangles.size(); ++t)
            if (!drop[t])
                triangles[kept++] = triangles[t];
        r.dropped_duplicate_faces = triangles.size() - kept;
        triangles.resize(kept);
    }

    // Compact: keep used vertices in their input order.
    constexpr uint32_t unused = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> new_index(nv, unused);
    for (const Triangle& t : triangles)
        for (const uint32_t i : t)
            new_index[i] = 0;
    std::vector<uint32_t> original;
    for (size_t i = 0; i < nv; ++i)
        if (new_index[i] != unused)
        {
            new_index[i] = static_cast<uint32_t>(original.size());
            original.push_back(static_cast<uint32_t>(i));
            out.mesh.positions.push_back(soup.positions[i]);
        }
    for (Triangle& t : triangles)
        for (uint32_t& i : t)
            i = new_index[i];
    for (size_t i = 0; i < nv; ++i)
        r.unreferenced_vertices += !non_finite[i] && target[i] == i && new_index[i] == unused;

    TopologyInfo topo = analyse_topology(out.mesh.positions, triangles);
    for (const uint8_t f : topo.flipped)
        r.flipped_faces += f;
    out.mesh.triangles = std::move(triangles);
    r.input_holes = topo.holes;
    r.input_boundary_edges = topo.boundary_edges;
    r.input_non_manifold_edges = topo.non_manifold_edges;
    r.input_non_manifold_vertices = topo.non_manifold_vertices;

    // The repairs a person would make (issue 36); a closed, manifold, one-part mesh skips them, so
    // such a mesh is exactly what it was before they existed.
    SurfaceClosing closing;
    // Coordinates that overflow are refused below; no area or normal of theirs means anything.
    if ((topo.boundary_edges || topo.non_manifold_edges || topo.non_manifold_vertices || topo.components > 1) &&
        !topo.non_orientable_components && !huge)
    {
        const size_t faces_before = out.mesh.triangles.size();
        closing = close_surface(out.mesh, original, options.thicken_sheets);
        const bool changed = closing.pinched_vertices || closing.split_edges || !closing.hole_edges.empty() ||
                             closing.specks || closing.sheets || closing.thickened_sheets ||
                             out.mesh.triangles.size() != faces_before;
        if (changed && !closing.only_sheets)
        {
            // An open part's outward side was a guess; closed, its volume tells. Faces count as
            // flipped when they end up reversed against the input.
            const std::vector<uint8_t> first = topo.flipped;
            topo = analyse_topology(out.mesh.positions, out.mesh.triangles);
            r.flipped_faces = 0;
            for (size_t f = 0; f < topo.flipped.size(); ++f)
                if (closing.source_face[f] != 0xFFFFFFFFu)
                    r.flipped_faces += first[closing.source_face[f]] != topo.flipped[f];
        }
    }
    r.filled_holes = closing.only_sheets ? 0 : closing.hole_edges.size();
    r.separated_pinched_vertices = closing.pinched_vertices;
    r.separated_edges = closing.split_edges;
    r.dropped_specks = closing.specks;
    r.dropped_sheets = closing.sheets;
    r.thickened_sheets = closing.thickened_sheets;

    // Parts that overlap are one solid: their inner walls go, the genus is the union's.
    OverlapMerge merged;
    if (topo.components > 1 && topo.boundary_edges == 0 && topo.non_manifold_edges == 0 &&
        topo.non_manifold_vertices == 0 && topo.non_orientable_components == 0 && !huge)
        merged = merge_overlapping_parts(out.mesh);

    r.vertices = out.mesh.positions.size();
    r.faces = out.mesh.triangles.size();
    r.edges = topo.edges;
    r.boundary_edges = topo.boundary_edges;
    r.holes = topo.holes;
    r.non_manifold_edges = topo.non_manifold_edges;
    r.non_manifold_vertices = topo.non_manifold_vertices;
    r.non_orientable_components = topo.non_orientable_components;
    r.components = topo.components;
    r.cavities = topo.cavities;
    r.euler = topo.euler;
    r.genus = topo.genus;
    r.joined_overlapping_parts = merged.joined_parts;
    if (merged.joined_parts)
    {
        r.components = merged.solids;
        r.genus = merged.genus;
        r.euler = 2 * static_cast<long long>(merged.solids) - 2 * merged.genus;
        r.faces = out.mesh.triangles.size();
    }
    r.closed = r.faces > 0 && topo.boundary_edges == 0;
    r.manifold = r.faces > 0 && topo.non_manifold_edges == 0 && topo.non_manifold_vertices == 0 &&
                 topo.non_orientable_components == 0;
    describe_repairs(r);
    for (std::string& line : describe_closing(closing))
        r.repairs.push_back(std::move(line));
    if (merged.joined_parts)
        r.repairs.push_back("joined " + plural(merged.joined_parts, "overlapping part", "overlapping parts") +
                            " into " + plural(merged.solids, "solid", "solids") + " (removed " +
                            plural(merged.removed_faces, "face", "faces") + " inside other parts)");
    describe_problems(r, topo, original, closing);
    if (huge)
        r.problems.push_back("coordinates are too large (the bounding box diagonal overflows); scale the model down");
    return out;
}

} // namespace

std::string SurfaceReport::problem_summary() const
{
    std::string s;
    for (const std::string& p : problems)
        s += (s.empty() ? "" : "; ") + p;
    return s;
}

SurfaceReport diagnose(const PolygonSoup& soup, const PrepareOptions& options) { return run(soup, options).report; }

PreparedSurface prepare_surface(const PolygonSoup& soup, const PrepareOptions& options)
{
    PreparedSurface prepared = run(soup, options);
    if (!prepared.report.ok())
        throw InvalidInputError(prepared.report.problem_summary());
    return prepared;
}

TriangleMesh load_surface(const std::string& path, const PrepareOptions& options)
{
    return prepare_surface(read_mesh_file(path), options).mesh;
}

} // namespace zomeify
