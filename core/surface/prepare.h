#pragma once
//! \file prepare.h
//! Diagnosis and repair of an imported surface (issue 3): weld duplicate vertices, drop degenerate
//! and duplicate faces, triangulate polygons, orient every component consistently and outward; then
//! separate pinched vertices and edges, close holes, drop specks and loose open sheets (issue 36),
//! check that the result is a closed 2-manifold and measure its topology.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/geom/triangle_mesh.h"
#include "core/surface/polygon_soup.h"

namespace zomeify {

//! What the diagnosis found and what the repair did. Counts refer to the soup as given (input_*)
//! or to the repaired triangle mesh (everything else). Vertex numbers in messages are 0-based
//! indices into the input soup's positions.
struct SurfaceReport
{
    // Input.
    size_t input_vertices = 0;
    size_t input_faces = 0; //!< polygons in the soup, whatever their size

    // Repairs (each one also adds a line to `repairs`).
    size_t welded_vertices = 0;          //!< vertices merged into an earlier one at the same place
    size_t unreferenced_vertices = 0;    //!< vertices used by no kept face, removed
    size_t dropped_small_faces = 0;      //!< faces with fewer than 3 vertices
    size_t dropped_invalid_faces = 0;    //!< faces using an index out of range or a non-finite vertex
    size_t dropped_degenerate_faces = 0; //!< repeated vertex or zero area
    size_t dropped_duplicate_faces = 0;  //!< same vertices, same orientation as an earlier face
    size_t triangulated_polygons = 0;    //!< polygons with more than 3 vertices
    size_t flipped_faces = 0;            //!< triangles whose orientation was reversed
    // Repairs of a mesh from the wild (close_surface.h).
    size_t filled_holes = 0;               //!< boundary loops closed with a patch
    size_t separated_pinched_vertices = 0; //!< vertices where separate fans of faces met
    size_t separated_edges = 0;            //!< edges that had more than two faces
    size_t dropped_specks = 0;             //!< parts under 1% of the mesh's size
    size_t dropped_sheets = 0;             //!< open sheets beside a solid
    size_t joined_overlapping_parts = 0;   //!< closed parts that overlap another, joined (merge_overlaps.h)
    size_t thickened_sheets = 0;           //!< open sheets given a thickness (PrepareOptions::thicken_sheets)

    // What the input had before those repairs (the same as the result's fields when none applied).
    size_t input_holes = 0;
    size_t input_boundary_edges = 0;
    size_t input_non_manifold_edges = 0;
    size_t input_non_manifold_vertices = 0;

    // Result.
    size_t vertices = 0;
    size_t faces = 0; //!< triangles
    size_t edges = 0;
    size_t non_finite_vertices = 0;   //!< NaN or infinite coordinates (faces using them are dropped)
    size_t boundary_edges = 0;        //!< edges with one face
    size_t holes = 0;                 //!< boundary loops
    size_t non_manifold_edges = 0;    //!< edges with more than two faces
    size_t non_manifold_vertices = 0; //!< vertices whose faces form more than one fan
    size_t non_orientable_components = 0;
    size_t components = 0; //!< connected by shared edges
    size_t cavities = 0;   //!< components inside an odd number of others, oriented inward
    long long euler = 0;   //!< V - E + F
    long long genus = 0;   //!< sum over components of (2 - chi - boundary loops) / 2
    bool closed = false;   //!< no boundary edges
    bool manifold = false; //!< no non-manifold edges or vertices, every component orientable
    std::array<double, 3> bbox_min{0, 0, 0};
    std::array<double, 3> bbox_max{0, 0, 0};

    std::vector<std::string> repairs;  //!< one line per repair that changed something
    std::vector<std::string> problems; //!< one line per problem that stops the pipeline

    //! Closed, manifold and not empty: prepare_surface accepts it.
    bool ok() const { return problems.empty(); }
    //! All problems joined into one line (empty when ok()).
    std::string problem_summary() const;
};

struct PrepareOptions
{
    //! Vertices closer than this times the bounding-box diagonal are welded. 0 welds exact duplicates only.
    double weld_tolerance = 1e-9;
    //! A triangle is degenerate if its area is at most this times the squared bounding-box diagonal.
    double degenerate_area = 1e-20;
    //! A mesh that is only open sheets (a terrain, a mask) is given a thickness and becomes a solid
    //! (`--thicken`, the page's "Give it a thickness"), instead of being refused.
    bool thicken_sheets = false;
};

struct PreparedSurface
{
    TriangleMesh mesh;
    SurfaceReport report;
};

//! Runs the whole repair without throwing for geometry problems; the report says what is wrong.
SurfaceReport diagnose(const PolygonSoup& soup, const PrepareOptions& options = {});

//! Repairs what is safe and returns the closed, consistently outward-oriented triangle mesh.
//! Throws InvalidInputError with report.problem_summary() (counts and a hint) otherwise.
PreparedSurface prepare_surface(const PolygonSoup& soup, const PrepareOptions& options = {});

//! read_mesh_file + prepare_surface.
TriangleMesh load_surface(const std::string& path, const PrepareOptions& options = {});

} // namespace zomeify
