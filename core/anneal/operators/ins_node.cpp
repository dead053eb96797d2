// INSNODE(f) (paper §3.2, §5.1): a new node inside face f, connected to every reachable corner.
// Its position is, with equal probability, SPLITVECTOR of a random oriented edge a → b of f (the
// node at a + v*) or CHANGEDIRECTIONS of two consecutive edges a → b → c (the node at a + w*).
#include "core/anneal/operators/exact_steps.h"
#include "core/anneal/operators/fan.h"
#include "core/anneal/operators/operators.h"
#include "core/anneal/operators/region.h"

namespace zomeify::detail {
namespace {

// The rest of INSNODE once the face's region is loaded.
Rejection fill_face(const ZomeMesh& mesh, const ZVec& p, Claims& claims, Fill& fill, LocalChange& change) noexcept
{
    if (const Rejection r = fan_fill(mesh, change, p, fill); r != Rejection::None)
        return r;
    return complete_fill(mesh, fill, claims, change);
}

} // namespace

Rejection ins_node_at(const ZomeMesh& mesh, Face f, const ZVec& p, Claims& claims, Fill& fill,
                      LocalChange& change) noexcept
{
    if (const Rejection r = load_face_region(mesh, f, claims, fill, change); r != Rejection::None)
        return r;
    return fill_face(mesh, p, claims, fill, change);
}

Rejection propose_ins_node(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                           LocalChange& change) noexcept
{
    const Face f = random_face(mesh, seed, rng, /*quads_only=*/false);
    if (!f.is_valid())
        return Rejection::NoCandidate;
    if (const Rejection r = load_face_region(mesh, f, claims, fill, change); r != Rejection::None)
        return r;
    const size_t k = fill.link_size();
    const size_t i = rng.below(k);
    const ZVec& a = fill.nodes()[i].pos;
    const ZVec& b = fill.nodes()[(i + 1) % k].pos;
    const std::optional<ZVec> p =
        rng.below(2) == 0
            ? split_position(a, vector_between(a, b), rng)
            : change_position(a, vector_between(a, b), vector_between(b, fill.nodes()[(i + 2) % k].pos), rng);
    if (!p)
        return Rejection::NoCandidate;
    return fill_face(mesh, *p, claims, fill, change);
}

} // namespace zomeify::detail
