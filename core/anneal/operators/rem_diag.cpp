// REMDIAG(s) (paper §3.2): removes the strut between two triangles (u, v, x) and (v, u, y), which
// become the quad (v, x, u, y). Refused when u or v would drop below valence 3 or x = y.
#include "core/anneal/operators/operators.h"
#include "core/anneal/operators/region.h"

namespace zomeify::detail {

Rejection rem_diag_at(const ZomeMesh& mesh, Halfedge h, Claims& claims, Fill& fill, LocalChange& change) noexcept
{
    if (const Rejection r = load_strut_region(mesh, h, claims, fill, change); r != Rejection::None)
        return r;
    if (fill.link_size() != 4)
        return Rejection::FaceSize; // the merged face would have 5 or more corners
    // Link: v, x, u, y.
    fill.add_quad(0, 1, 2, 3);
    return complete_fill(mesh, fill, claims, change);
}

Rejection propose_rem_diag(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                           LocalChange& change) noexcept
{
    const Halfedge h = random_diagonal(mesh, seed, rng);
    return h.is_valid() ? rem_diag_at(mesh, h, claims, fill, change) : Rejection::NoCandidate;
}

} // namespace zomeify::detail
