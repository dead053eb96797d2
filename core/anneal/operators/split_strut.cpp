// SPLITSTRUT(s) (paper §3.2, §5.1): a new node p on a SPLITVECTOR split of strut u → v
// (p = u + v*, v = p + v'), replacing s and its two faces by a fan from p that must include u and
// v and connects every other reachable link node. A collinear split (b2 = b0 + b1) keeps the
// direction of s: s's slots at u and v are free because s is removed.
#include "core/anneal/operators/exact_steps.h"
#include "core/anneal/operators/fan.h"
#include "core/anneal/operators/operators.h"
#include "core/anneal/operators/region.h"

namespace zomeify::detail {

Rejection split_strut_at(const ZomeMesh& mesh, Halfedge h, const ZVec& p, Claims& claims, Fill& fill,
                         LocalChange& change) noexcept
{
    // Link: v at 0, then h's face's other corners, u, then the opposite face's other corners.
    const size_t u_index = mesh.valence(mesh.face(h)) - 1;
    if (const Rejection r = load_strut_region(mesh, h, claims, fill, change); r != Rejection::None)
        return r;
    if (const Rejection r = fan_fill(mesh, change, p, fill, u_index, 0); r != Rejection::None)
        return r;
    return complete_fill(mesh, fill, claims, change);
}

Rejection propose_split_strut(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                              LocalChange& change) noexcept
{
    const Halfedge h = random_strut(mesh, seed, rng);
    if (!h.is_valid())
        return Rejection::NoCandidate;
    const int id = mesh.vector_id(h) == kNoZomeVector ? -1 : mesh.vector_id(h);
    const std::optional<ZVec> p = split_position(mesh.position(seed), id, rng);
    if (!p)
        return Rejection::NoCandidate;
    return split_strut_at(mesh, h, *p, claims, fill, change);
}

} // namespace zomeify::detail
