#include "core/anneal/operators/fill.h"

#include <algorithm>

#include "core/anneal/operators/exact_steps.h"
#include "core/mesh/circulators.h"

namespace zomeify::detail {
namespace {

// A strut of the fill that is not a link edge, with the Zome vector id of nodes[a] → nodes[b].
struct FillStrut
{
    uint8_t a = 0, b = 0;
    int id = -1;
    bool seen_back = false; // used by the second face, in the opposite direction
};
using FillStruts = FixedList<FillStrut, LocalChange::kMaxStruts>;

bool removed(const LocalChange& change, Edge e) noexcept
{
    return std::find(change.removed_struts().begin(), change.removed_struts().end(), e) !=
           change.removed_struts().end();
}

// Collects the new struts and checks that the faces form a disc over the link.
Rejection collect_struts(const Fill& fill, FillStruts& struts) noexcept
{
    uint64_t link_edges = 0;
    for (const FillFace& f : fill.faces())
    {
        for (size_t j = 0; j < f.size; ++j)
        {
            const uint8_t a = f.corners[j], b = f.corners[(j + 1) % f.size];
            if (a == b)
                return Rejection::Topology;
            if (fill.is_link_edge(a, b))
            {
                const uint64_t bit = uint64_t{1} << a;
                if (link_edges & bit)
                    return Rejection::Topology;
                link_edges |= bit;
                continue;
            }
            auto same = [&](const FillStrut& s) { return s.a == a && s.b == b; };
            auto back = [&](const FillStrut& s) { return s.a == b && s.b == a; };
            if (std::any_of(struts.begin(), struts.end(), same))
                return Rejection::Topology;
            FillStrut* const end = &struts[0] + struts.size();
            FillStrut* const it = std::find_if(&struts[0], end, back);
            if (it != end)
            {
                it->seen_back = true;
                continue;
            }
            const int id = vector_between(fill.nodes()[a].pos, fill.nodes()[b].pos);
            if (id < 0)
                return Rejection::NoCandidate;
            if (!struts.push_back({a, b, id, false}))
                return Rejection::Overflow;
        }
    }
    const uint64_t all = fill.link_size() >= 64 ? ~uint64_t{0} : (uint64_t{1} << fill.link_size()) - 1;
    if (link_edges != all)
        return Rejection::Topology;
    for (const FillStrut& s : struts)
        if (!s.seen_back)
            return Rejection::Topology;
    return Rejection::None;
}

// The slots that the new struts take at node i, and the fill node at each one's other end.
struct NodeSlots
{
    FixedList<int, 64> slots;
    FixedList<uint8_t, 64> others;
};

Rejection slots_at(const FillStruts& struts, size_t i, NodeSlots& out) noexcept
{
    out.slots.clear();
    out.others.clear();
    for (const FillStrut& s : struts)
    {
        int slot = -1;
        uint8_t other = 0;
        if (s.a == i)
        {
            slot = vector_slot(s.id);
            other = s.b;
        }
        else if (s.b == i)
        {
            slot = opposite_slot(vector_slot(s.id));
            other = s.a;
        }
        else
        {
            continue;
        }
        if (std::find(out.slots.begin(), out.slots.end(), slot) != out.slots.end())
            return Rejection::SlotConflict;
        out.slots.push_back(slot);
        out.others.push_back(other);
    }
    return Rejection::None;
}

// Checks one surviving node: its kept struts against the new ones, and its valence afterwards.
// Sets `changed` when its set of struts changes.
Rejection check_surviving(const ZomeMesh& mesh, const Fill& fill, const LocalChange& change, Vertex v,
                          const NodeSlots& mine, bool& changed) noexcept
{
    size_t kept = 0, before = 0;
    for (Halfedge h : outgoing_halfedges(mesh, v))
    {
        ++before;
        if (removed(change, ZomeMesh::edge(h)))
            continue;
        ++kept;
        const int slot = mesh.slot(h);
        for (size_t k = 0; k < mine.slots.size(); ++k)
        {
            if (mine.slots[k] == slot)
                return mesh.to_vertex(h) == fill.nodes()[mine.others[k]].v ? Rejection::DoubleStrut
                                                                           : Rejection::SlotConflict;
        }
    }
    changed = kept != before || !mine.slots.empty();
    return kept + mine.slots.size() < 3 ? Rejection::Valence : Rejection::None;
}

bool removed_face(const LocalChange& change, Face f) noexcept
{
    return std::find(change.removed_faces().begin(), change.removed_faces().end(), f) != change.removed_faces().end();
}

// Whether fill nodes a and b end up joined by a strut: a new one, or a surviving one.
bool joined_after(const ZomeMesh& mesh, const Fill& fill, const FillStruts& struts, const LocalChange& change,
                  uint8_t a, uint8_t b) noexcept
{
    if (fill.is_link_edge(a, b) || fill.is_link_edge(b, a))
        return true;
    for (const FillStrut& s : struts)
        if ((s.a == a && s.b == b) || (s.a == b && s.b == a))
            return true;
    const Vertex va = fill.nodes()[a].v, vb = fill.nodes()[b].v;
    if (!va.is_valid() || !vb.is_valid())
        return false;
    const Halfedge h = mesh.find_halfedge(va, vb);
    return h.is_valid() && !removed(change, ZomeMesh::edge(h));
}

// A quad whose diagonal is also a strut folds two faces onto each other: the Zome model cannot
// be built that way (paper §3.2: fold-overs lead to strut collisions). Refused both ways: a new
// quad over a joined diagonal, and a new strut across a surviving quad. Reads only faces at
// claimed link nodes.
Rejection check_quad_diagonals(const ZomeMesh& mesh, const Fill& fill, const FillStruts& struts,
                               const LocalChange& change) noexcept
{
    for (const FillFace& f : fill.faces())
        if (f.size == 4 && (joined_after(mesh, fill, struts, change, f.corners[0], f.corners[2]) ||
                            joined_after(mesh, fill, struts, change, f.corners[1], f.corners[3])))
            return Rejection::FoldedQuad;
    for (const FillStrut& s : struts)
    {
        const Vertex va = fill.nodes()[s.a].v, vb = fill.nodes()[s.b].v;
        if (!va.is_valid() || !vb.is_valid())
            continue;
        for (Halfedge h : outgoing_halfedges(mesh, va))
        {
            const Face f = mesh.face(h);
            if (!f.is_valid() || removed_face(change, f) || mesh.valence(f) != 4)
                continue;
            // h leaves va along f; the corner two steps on is va's opposite corner in f.
            if (mesh.to_vertex(mesh.next(h)) == vb)
                return Rejection::FoldedQuad;
        }
    }
    return Rejection::None;
}

} // namespace

bool position_usable(const ZomeMesh& mesh, const LocalChange& change, const ZVec& p) noexcept
{
    const Vertex at = mesh.find_vertex(p);
    return !at.is_valid() ||
           std::find(change.removed_nodes().begin(), change.removed_nodes().end(), at) != change.removed_nodes().end();
}

bool Fill::add_face(std::array<size_t, 4> c, uint8_t size) noexcept
{
    FillFace f;
    f.size = size;
    for (size_t i = 0; i < size; ++i)
    {
        if (c[i] >= nodes_.size())
            return false;
        f.corners[i] = static_cast<uint8_t>(c[i]);
    }
    return faces_.push_back(f);
}

bool Fill::add_fan_face(size_t centre, size_t from, size_t to) noexcept
{
    const size_t k = link_size_;
    const size_t gap = (to + k - from) % k;
    if (gap == 1)
        return add_triangle(centre, from, to);
    if (gap == 2)
        return add_quad(centre, from, (from + 1) % k, to);
    return false;
}

bool Fill::link_is_simple() const noexcept
{
    for (size_t i = 0; i < link_size_; ++i)
        for (size_t j = i + 1; j < link_size_; ++j)
            if (nodes_[i].v == nodes_[j].v)
                return false;
    return true;
}

Rejection claim(Claims& claims, Vertex v) noexcept
{
    if (claims.take(v))
        return Rejection::None;
    return claims.held().size() == Claims::kMaxNodes ? Rejection::Overflow : Rejection::Busy;
}

bool keeps_strut_in_slot(const ZomeMesh& mesh, Vertex v, int slot, const LocalChange& change) noexcept
{
    for (Halfedge h : outgoing_halfedges(mesh, v))
        if (mesh.slot(h) == slot && !removed(change, ZomeMesh::edge(h)))
            return true;
    return false;
}

Rejection complete_fill(const ZomeMesh& mesh, const Fill& fill, Claims& claims, LocalChange& change) noexcept
{
    if (fill.overflowed())
        return Rejection::Overflow;
    FillStruts struts;
    if (const Rejection r = collect_struts(fill, struts); r != Rejection::None)
        return r;

    // Slots first, then valence, so a doubly connected pair is reported as such even when it
    // also leaves a node with too few struts.
    FixedList<Vertex, kMaxFillNodes> changed_nodes;
    NodeSlots mine;
    Rejection low_valence = Rejection::None;
    for (size_t i = 0; i < fill.nodes().size(); ++i)
    {
        if (const Rejection r = slots_at(struts, i, mine); r != Rejection::None)
            return r;
        const FillNode& node = fill.nodes()[i];
        if (!node.v.is_valid())
        {
            if (!position_usable(mesh, change, node.pos))
                return Rejection::Occupied;
            if (mine.slots.size() < 3)
                low_valence = Rejection::Valence;
            continue;
        }
        bool changed = false;
        const Rejection r = check_surviving(mesh, fill, change, node.v, mine, changed);
        if (r == Rejection::Valence)
            low_valence = r;
        else if (r != Rejection::None)
            return r;
        if (changed)
            changed_nodes.push_back(node.v);
    }
    if (low_valence != Rejection::None)
        return low_valence;
    if (const Rejection r = check_quad_diagonals(mesh, fill, struts, change); r != Rejection::None)
        return r;

    // E_fair of a node whose struts change reads its neighbours' positions: claim them.
    for (Vertex v : changed_nodes)
        for (Vertex w : adjacent_vertices(mesh, v))
            if (const Rejection r = claim(claims, w); r != Rejection::None)
                return r;

    for (const FillNode& node : fill.nodes())
        if (!node.v.is_valid())
            change.add_node(node.pos);
    for (const FillStrut& s : struts)
        change.add_strut(fill.nodes()[s.a].pos, fill.nodes()[s.b].pos);
    for (const FillFace& f : fill.faces())
    {
        std::array<ZVec, 4> corners;
        for (size_t j = 0; j < f.size; ++j)
            corners[j] = fill.nodes()[f.corners[j]].pos;
        change.add_face(std::span<const ZVec>(corners.data(), f.size));
    }
    return change.overflowed() ? Rejection::Overflow : Rejection::None;
}

} // namespace zomeify::detail
