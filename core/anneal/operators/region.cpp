#include "core/anneal/operators/region.h"

#include "core/mesh/circulators.h"

namespace zomeify::detail {
namespace {

// Outgoing halfedges of the seed that pass `keep`; a uniformly random one, or invalid.
template <class Keep>
Halfedge random_outgoing(const ZomeMesh& mesh, Vertex seed, Rng& rng, Keep keep) noexcept
{
    FixedList<Halfedge, kSlotCount> candidates;
    for (Halfedge h : outgoing_halfedges(mesh, seed))
        if (keep(h))
            candidates.push_back(h);
    if (candidates.empty())
        return Halfedge();
    return candidates[rng.below(candidates.size())];
}

bool is_triangle(const ZomeMesh& mesh, Halfedge h) noexcept
{
    return !mesh.is_boundary(h) && mesh.next(mesh.next(mesh.next(h))) == h;
}

bool is_quad(const ZomeMesh& mesh, Halfedge h) noexcept
{
    return !mesh.is_boundary(h) && mesh.next(mesh.next(mesh.next(mesh.next(h)))) == h && !is_triangle(mesh, h);
}

Rejection add_and_claim(const ZomeMesh& mesh, Vertex v, Claims& claims, Fill& fill) noexcept
{
    if (const Rejection r = claim(claims, v); r != Rejection::None)
        return r;
    return fill.add_link_node(mesh, v) ? Rejection::None : Rejection::Overflow;
}

} // namespace

Halfedge random_strut(const ZomeMesh& mesh, Vertex seed, Rng& rng) noexcept
{
    return random_outgoing(mesh, seed, rng, [](Halfedge) { return true; });
}

Halfedge random_diagonal(const ZomeMesh& mesh, Vertex seed, Rng& rng) noexcept
{
    return random_outgoing(
        mesh, seed, rng, [&](Halfedge h) { return is_triangle(mesh, h) && is_triangle(mesh, ZomeMesh::opposite(h)); });
}

Face random_face(const ZomeMesh& mesh, Vertex seed, Rng& rng, bool quads_only) noexcept
{
    const Halfedge h = random_outgoing(
        mesh, seed, rng, [&](Halfedge x) { return !mesh.is_boundary(x) && (!quads_only || is_quad(mesh, x)); });
    return h.is_valid() ? mesh.face(h) : Face();
}

Rejection load_face_region(const ZomeMesh& mesh, Face f, Claims& claims, Fill& fill, LocalChange& change) noexcept
{
    fill.clear();
    for (Vertex v : face_vertices(mesh, f))
        if (const Rejection r = add_and_claim(mesh, v, claims, fill); r != Rejection::None)
            return r;
    return change.remove_face(f) ? Rejection::None : Rejection::Overflow;
}

Rejection load_strut_region(const ZomeMesh& mesh, Halfedge h, Claims& claims, Fill& fill, LocalChange& change) noexcept
{
    fill.clear();
    for (const Halfedge side : {h, ZomeMesh::opposite(h)})
    {
        if (mesh.is_boundary(side))
            return Rejection::Topology;
        for (Halfedge x = mesh.next(side); x != side; x = mesh.next(x))
            if (const Rejection r = add_and_claim(mesh, mesh.from_vertex(x), claims, fill); r != Rejection::None)
                return r;
        change.remove_face(mesh.face(side));
    }
    change.remove_strut(ZomeMesh::edge(h));
    if (!fill.link_is_simple())
        return Rejection::LinkTwice;
    return change.overflowed() ? Rejection::Overflow : Rejection::None;
}

Rejection load_node_region(const ZomeMesh& mesh, Vertex n, Claims& claims, Fill& fill, LocalChange& change) noexcept
{
    fill.clear();
    const Halfedge start = mesh.halfedge(n);
    if (!start.is_valid() || mesh.is_boundary(start))
        return Rejection::Topology;
    Halfedge h = start;
    do
    {
        // The corners of this face after n, except the last (it starts the next face).
        const Halfedge last = mesh.prev(h);
        for (Halfedge x = mesh.next(h); x != last; x = mesh.next(x))
            if (const Rejection r = add_and_claim(mesh, mesh.from_vertex(x), claims, fill); r != Rejection::None)
                return r;
        h = mesh.ccw_rotated(h);
    } while (h != start);
    if (!fill.link_is_simple())
        return Rejection::LinkTwice;
    return change.remove_star(mesh, n) ? Rejection::None : Rejection::Overflow;
}

} // namespace zomeify::detail
