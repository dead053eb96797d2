// MOVNODE(n) (paper §3.2, §5.1): n's star is cleared and n comes back at a new position p,
// connected to every reachable link node. p is, with equal probability, SPLITVECTOR of a random
// oriented link edge a → b (p = a + v*), or CHANGEDIRECTIONS of two random struts through n,
// a → n → b (p = a + w*: "moving the node between the struts"; we take the two struts at n rather
// than two link edges because they describe n's own position). p = n's position is refused (it
// would only re-fan the same node); p at any other node is Occupied.
#include "core/anneal/operators/exact_steps.h"
#include "core/anneal/operators/fan.h"
#include "core/anneal/operators/operators.h"
#include "core/anneal/operators/region.h"
#include "core/mesh/circulators.h"

namespace zomeify::detail {
namespace {

std::optional<ZVec> between_two_struts(const ZomeMesh& mesh, Vertex n, Rng& rng) noexcept
{
    const size_t d = mesh.valence(n);
    if (d < 2)
        return std::nullopt;
    const size_t i = rng.below(d);
    const size_t j = (i + 1 + rng.below(d - 1)) % d; // a different strut
    Halfedge in, out;
    size_t k = 0;
    for (Halfedge h : outgoing_halfedges(mesh, n))
    {
        if (k == i)
            in = ZomeMesh::opposite(h);
        if (k == j)
            out = h;
        ++k;
    }
    const int a = mesh.vector_id(in), b = mesh.vector_id(out);
    if (a == kNoZomeVector || b == kNoZomeVector)
        return std::nullopt;
    return change_position(mesh.position(mesh.from_vertex(in)), a, b, rng);
}

// The rest of MOVNODE once n's region is loaded.
Rejection fill_star(const ZomeMesh& mesh, Vertex n, const ZVec& p, Claims& claims, Fill& fill,
                    LocalChange& change) noexcept
{
    if (p == mesh.position(n))
        return Rejection::NoCandidate;
    if (const Rejection r = fan_fill(mesh, change, p, fill); r != Rejection::None)
        return r;
    return complete_fill(mesh, fill, claims, change);
}

} // namespace

Rejection mov_node_to(const ZomeMesh& mesh, Vertex n, const ZVec& p, Claims& claims, Fill& fill,
                      LocalChange& change) noexcept
{
    if (const Rejection r = load_node_region(mesh, n, claims, fill, change); r != Rejection::None)
        return r;
    return fill_star(mesh, n, p, claims, fill, change);
}

Rejection propose_mov_node(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                           LocalChange& change) noexcept
{
    if (const Rejection r = load_node_region(mesh, seed, claims, fill, change); r != Rejection::None)
        return r;
    std::optional<ZVec> p;
    if (rng.below(2) == 0)
    {
        const size_t k = fill.link_size();
        const size_t i = rng.below(k);
        const ZVec& a = fill.nodes()[i].pos;
        p = split_position(a, vector_between(a, fill.nodes()[(i + 1) % k].pos), rng);
    }
    else
    {
        p = between_two_struts(mesh, seed, rng);
    }
    if (!p)
        return Rejection::NoCandidate;
    return fill_star(mesh, seed, *p, claims, fill, change);
}

} // namespace zomeify::detail
