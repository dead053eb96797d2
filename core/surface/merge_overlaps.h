#pragma once
//! \file merge_overlaps.h
//! Closed parts that overlap, as files often hold them (a mug's handle pushed into its body, an
//! animal's legs into its torso): the solid meant is their union (issue 36). The faces of each part
//! that lie inside another part are walls inside that solid, no surface to approximate, so they
//! are removed; what remains is the union's outer surface, open only along the curves where the
//! parts cross. Its genus is the union's: χ of the remaining faces, counted per glued group.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

struct OverlapMerge
{
    size_t joined_parts = 0;  //!< parts that overlap another (0: nothing changed)
    size_t removed_faces = 0; //!< faces inside another part, removed
    size_t solids = 0;        //!< connected solids after joining (outer shells and cavities counted apart)
    long long genus = 0;      //!< of the union's surface, summed over its shells
    size_t seam_edges = 0;    //!< edges left with one face, along the crossings
};

//! Finds closed, outward parts whose faces lie partly inside another such part (by that part's
//! angle-weighted pseudo-normals, exact for a closed part) and removes those faces. `mesh` must be
//! closed, manifold and oriented (analyse_topology); it is changed only when parts overlap.
OverlapMerge merge_overlapping_parts(TriangleMesh& mesh);

} // namespace zomeify
