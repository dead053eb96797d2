#pragma once
//! \file close_surface.h
//! The repairs a person would make to a mesh from the wild before it can become a solid (issue 36):
//! separate pinched vertices and edges with more than two faces (split_non_manifold.h), close the
//! holes (fill_holes.h), and drop what cannot be part of a Zome model: specks far smaller than a
//! strut, and open sheets beside a solid. A mesh that is only open sheets has no inside to fill.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! A part smaller than this fraction of the whole mesh's bounding-box diagonal is a speck: at the
//! finest grid the automatic choice searches (64 cells) a cell is about 1.6% of the longest side.
inline constexpr double kSpeckFraction = 0.01;
//! A part whose largest hole's patch would add this fraction of its own area or more is an open
//! sheet (a terrain, a mask, a bowl, a single quad: one open edge runs around the whole shape), not
//! a solid with a few holes (a bust's open base, a tube's two ends).
inline constexpr double kSheetPatchFraction = 0.4;

struct SurfaceClosing
{
    size_t pinched_vertices = 0;
    size_t split_edges = 0;
    std::vector<size_t> hole_edges; //!< boundary edges of each hole closed, in the order found
    size_t specks = 0;              //!< parts dropped as specks
    size_t speck_faces = 0;
    size_t sheets = 0; //!< open sheets dropped beside a solid
    size_t sheet_faces = 0;
    size_t sheet_boundary_edges = 0; //!< of the largest sheet, when every part is one (the refusal)
    double sheet_patch_ratio = 0.0;  //!< its largest patch's area over its own area
    bool only_sheets = false;        //!< every part is an open sheet: no solid to build (without thicken)
    size_t thickened_sheets = 0;     //!< with thicken: the sheets given a thickness
    double thickness = 0.0;          //!< the thickness they got (mesh units)
    //! Per face of the result: the face it was before closing, or 0xFFFFFFFF for a patch.
    std::vector<uint32_t> source_face;
};

//! Repairs `mesh` in place (vertices are only appended or removed; `origin` maps each vertex to the
//! input vertex it copies, or 0xFFFFFFFF for new ones). Faces must be oriented consistently where
//! they can be (analyse_topology with orient); call analyse_topology again afterwards. With
//! `thicken`, a mesh that is only open sheets is made solid by giving them a thickness
//! (thicken_sheet.h) instead of being refused.
SurfaceClosing close_surface(TriangleMesh& mesh, std::vector<uint32_t>& origin, bool thicken = false);

//! The repairs in plain words, one line each ("closed 2 small holes (3 edges each)").
std::vector<std::string> describe_closing(const SurfaceClosing& c);

} // namespace zomeify
