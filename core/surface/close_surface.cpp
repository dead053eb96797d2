#include "core/surface/close_surface.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>

#include <Eigen/Geometry>

#include "core/surface/face_parts.h"
#include "core/surface/fill_holes.h"
#include "core/surface/split_non_manifold.h"
#include "core/surface/thicken_sheet.h"

namespace zomeify {

namespace {

using Triangle = std::array<uint32_t, 3>;
constexpr uint32_t none = 0xFFFFFFFFu;

std::string plural(size_t n, const std::string& one, const std::string& many)
{
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

double triangle_area(const TriangleMesh& m, const Triangle& t)
{
    return 0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm();
}

// Drops the faces not kept and the vertices no face uses (origin and source follow).
void keep_faces(TriangleMesh& mesh, std::vector<uint32_t>& origin, std::vector<uint32_t>& source,
                const std::vector<uint8_t>& keep)
{
    size_t kept = 0;
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        if (keep[f])
        {
            source[kept] = source[f];
            mesh.triangles[kept++] = mesh.triangles[f];
        }
    mesh.triangles.resize(kept);
    source.resize(kept);
    drop_unused_vertices(mesh, &origin);
}

std::string hole_sizes(std::vector<size_t> edges)
{
    std::sort(edges.begin(), edges.end());
    if (edges.front() == edges.back())
        return edges.size() == 1 ? plural(edges.front(), "edge", "edges")
                                 : plural(edges.front(), "edge", "edges") + " each";
    if (edges.size() <= 3)
    {
        std::string s;
        for (size_t i = 0; i < edges.size(); ++i)
            s += (i == 0 ? "" : i + 1 == edges.size() ? " and " : ", ") + std::to_string(edges[i]);
        return s + " edges";
    }
    return std::to_string(edges.front()) + " to " + std::to_string(edges.back()) + " edges";
}

} // namespace

SurfaceClosing close_surface(TriangleMesh& mesh, std::vector<uint32_t>& origin, bool thicken)
{
    SurfaceClosing out;
    const NonManifoldSplit split = split_non_manifold(mesh.positions, mesh.triangles, origin);
    out.pinched_vertices = split.pinched_vertices;
    out.split_edges = split.split_edges;
    const size_t original_faces = mesh.triangles.size();
    const HoleFilling filling = fill_holes(mesh.positions, mesh.triangles, origin);
    out.source_face.resize(mesh.triangles.size(), none);
    std::iota(out.source_face.begin(), out.source_face.begin() + static_cast<std::ptrdiff_t>(original_faces),
              uint32_t{0});

    // Per part: its size, its own area and its largest patch's area.
    size_t parts = 0;
    const std::vector<uint32_t> part = face_parts(mesh.triangles, parts);
    std::vector<double> own(parts, 0.0), largest_patch(parts, 0.0);
    std::vector<size_t> faces(parts, 0), rim(parts, 0);
    std::vector<Vec3> lo(parts, Vec3::Constant(std::numeric_limits<double>::infinity()));
    std::vector<Vec3> hi(parts, Vec3::Constant(-std::numeric_limits<double>::infinity()));
    Vec3 all_lo = Vec3::Constant(std::numeric_limits<double>::infinity()), all_hi = -all_lo;
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
    {
        const uint32_t p = part[f];
        if (f < original_faces)
        {
            own[p] += triangle_area(mesh, mesh.triangles[f]);
            ++faces[p];
        }
        for (const uint32_t v : mesh.triangles[f])
        {
            lo[p] = lo[p].cwiseMin(mesh.positions[v]);
            hi[p] = hi[p].cwiseMax(mesh.positions[v]);
        }
    }
    for (const FilledHole& h : filling.holes)
    {
        rim[part[h.neighbour]] += h.edges;
        largest_patch[part[h.neighbour]] = std::max(largest_patch[part[h.neighbour]], h.area);
    }
    for (size_t p = 0; p < parts; ++p)
    {
        all_lo = all_lo.cwiseMin(lo[p]);
        all_hi = all_hi.cwiseMax(hi[p]);
    }
    const double diagonal = parts ? (all_hi - all_lo).norm() : 0.0;

    // A sheet is judged first: a tiny flake beside a solid goes either way, and with no solid at
    // all, a sheet (not its size) is the reason to refuse.
    enum Kind : uint8_t
    {
        solid,
        speck,
        sheet
    };
    std::vector<uint8_t> kind(parts, solid);
    for (size_t p = 0; p < parts; ++p)
        if (largest_patch[p] > 0 && largest_patch[p] >= kSheetPatchFraction * own[p])
            kind[p] = sheet;
        else if ((hi[p] - lo[p]).norm() < kSpeckFraction * diagonal)
            kind[p] = speck;
    for (const FilledHole& h : filling.holes)
        if (kind[part[h.neighbour]] == solid)
            out.hole_edges.push_back(h.edges);
    if (std::find(kind.begin(), kind.end(), uint8_t{solid}) == kind.end())
    {
        // Nothing to keep a speck or a sheet beside. With a sheet, the largest one is the shape and
        // it is open; with only specks (closed), they are the shape and stay.
        size_t largest = parts;
        for (size_t p = 0; p < parts; ++p)
            if (kind[p] == sheet && (largest == parts || own[p] > own[largest]))
                largest = p;
        if (largest != parts && thicken)
        {
            // The predictable closed version the user asked for: every sheet given a thickness.
            std::vector<uint8_t> sheet_face(mesh.triangles.size(), 0);
            for (size_t f = 0; f < original_faces; ++f)
                sheet_face[f] = kind[part[f]] == sheet;
            keep_faces(mesh, origin, out.source_face, sheet_face);
            out.thickness = thicken_sheets(mesh, std::vector<uint8_t>(mesh.triangles.size(), 1));
            for (size_t p = 0; p < parts; ++p)
                out.thickened_sheets += kind[p] == sheet;
            origin.assign(mesh.positions.size(), none);
            out.source_face.assign(mesh.triangles.size(), none);
        }
        else if (largest != parts)
        {
            out.only_sheets = true;
            out.sheet_boundary_edges = rim[largest];
            out.sheet_patch_ratio = own[largest] > 0 ? largest_patch[largest] / own[largest] : 0.0;
        }
        else
            for (const FilledHole& h : filling.holes)
                out.hole_edges.push_back(h.edges);
        return out;
    }

    std::vector<uint8_t> keep(mesh.triangles.size(), 1);
    for (size_t p = 0; p < parts; ++p)
        if (kind[p] == speck)
        {
            ++out.specks;
            out.speck_faces += faces[p];
        }
        else if (kind[p] == sheet)
        {
            ++out.sheets;
            out.sheet_faces += faces[p];
        }
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        keep[f] = kind[part[f]] == solid;
    if (out.specks || out.sheets)
        keep_faces(mesh, origin, out.source_face, keep);
    return out;
}

std::vector<std::string> describe_closing(const SurfaceClosing& c)
{
    std::vector<std::string> lines;
    if (!c.hole_edges.empty() && !c.only_sheets)
    {
        const size_t largest = *std::max_element(c.hole_edges.begin(), c.hole_edges.end());
        lines.push_back("closed " +
                        plural(c.hole_edges.size(), largest <= 12 ? "small hole" : "hole",
                               largest <= 12 ? "small holes" : "holes") +
                        " (" + hole_sizes(c.hole_edges) + ")");
    }
    if (c.pinched_vertices)
        lines.push_back("separated " + plural(c.pinched_vertices, "pinched vertex", "pinched vertices") +
                        " (two fans of faces meeting at a point)");
    if (c.split_edges)
        lines.push_back(
            "separated the faces at " +
            plural(c.split_edges, "edge shared by more than two faces", "edges shared by more than two faces") +
            " into pairs that each close a solid");
    if (c.specks)
        lines.push_back("dropped " + plural(c.specks, "speck", "specks") + " (" +
                        plural(c.speck_faces, "face", "faces") + ", each under 1% of the mesh's size)");
    if (c.sheets)
        lines.push_back("dropped " + plural(c.sheets, "open sheet", "open sheets") + " beside the solid (" +
                        plural(c.sheet_faces, "face", "faces") + ")");
    if (c.thickened_sheets)
    {
        std::ostringstream t;
        t << std::setprecision(3) << c.thickness;
        lines.push_back("gave the open " + std::string(c.thickened_sheets == 1 ? "sheet" : "sheets") +
                        " a thickness of " + t.str() + " (" +
                        std::to_string(static_cast<int>(std::lround(100 * kSheetThicknessFraction))) +
                        "% of the longest side) to make a solid");
    }
    return lines;
}

} // namespace zomeify
