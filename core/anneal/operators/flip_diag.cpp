// FLIPDIAG(s) (paper §3.2): replaces the strut u–v between triangles (u, v, x) and (v, u, y) by
// x–y, giving (x, u, y) and (y, v, x). Refused when x–y is no Zome vector, a slot at x or y is
// taken, x and y are already joined (the flip "to an existing edge", e.g. in a tetrahedron, which
// would connect them twice), or u or v would drop below valence 3.
#include "core/anneal/operators/operators.h"
#include "core/anneal/operators/region.h"

namespace zomeify::detail {

Rejection flip_diag_at(const ZomeMesh& mesh, Halfedge h, Claims& claims, Fill& fill, LocalChange& change) noexcept
{
    if (const Rejection r = load_strut_region(mesh, h, claims, fill, change); r != Rejection::None)
        return r;
    if (fill.link_size() != 4)
        return Rejection::FaceSize; // not two triangles
    // Link: v, x, u, y.
    fill.add_triangle(1, 2, 3);
    fill.add_triangle(3, 0, 1);
    return complete_fill(mesh, fill, claims, change);
}

Rejection propose_flip_diag(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                            LocalChange& change) noexcept
{
    const Halfedge h = random_diagonal(mesh, seed, rng);
    return h.is_valid() ? flip_diag_at(mesh, h, claims, fill, change) : Rejection::NoCandidate;
}

} // namespace zomeify::detail
