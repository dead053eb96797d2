// mirror_proposal() (mirrored.h): the mirror image of a change, and the checks that let the change
// and its image be applied together. Each of the two is valid on the symmetric model by itself;
// what can go wrong together happens only where they meet: an element both would remove or add,
// and a node both give new struts (slots, valence) or where a quad of one has a strut of the other
// as its diagonal.
#include "core/anneal/operators/mirrored.h"

#include <algorithm>
#include <array>
#include <exception>

#include "core/mesh/circulators.h"
#include "core/zome/slots.h"

namespace zomeify {
namespace {

template <class List, class T>
bool contains(const List& list, const T& x) noexcept
{
    return std::find(list.begin(), list.end(), x) != list.end();
}

bool same_strut(const NewStrut& s, const NewStrut& t) noexcept
{
    return (s.a == t.a && s.b == t.b) || (s.a == t.b && s.b == t.a);
}

// The corners of a face in a canonical rotation (the smallest corner first), so two descriptions
// of one oriented face compare equal.
NewFace canonical(const NewFace& f) noexcept
{
    size_t first = 0;
    for (size_t i = 1; i < f.size; ++i)
        if (f.corners[i] < f.corners[first])
            first = i;
    NewFace out;
    out.size = f.size;
    for (size_t i = 0; i < f.size; ++i)
        out.corners[i] = f.corners[(first + i) % f.size];
    return out;
}

bool same_face(const NewFace& f, const NewFace& g) noexcept
{
    if (f.size != g.size)
        return false;
    const NewFace a = canonical(f), b = canonical(g);
    return std::equal(a.corners.begin(), a.corners.begin() + a.size, b.corners.begin());
}

template <class List>
bool same_set(const List& a, const List& b) noexcept
{
    if (a.size() != b.size())
        return false;
    for (const auto& x : a)
        if (!contains(b, x))
            return false;
    return true;
}

bool same_face_set(const LocalChange& c, const LocalChange& m) noexcept
{
    if (c.added_faces().size() != m.added_faces().size())
        return false;
    for (const NewFace& f : c.added_faces())
        if (std::none_of(m.added_faces().begin(), m.added_faces().end(),
                         [&](const NewFace& g) { return same_face(f, g); }))
            return false;
    return true;
}

class Mirroring
{
public:
    Mirroring(const ZomeMesh& mesh, const LatticeMirror& mirror, Claims& claims) noexcept
        : mesh_(mesh), mirror_(mirror), claims_(claims)
    {
    }

    // The mirror image of `c` in `m` (nodes claimed). Rejection::None when it exists.
    Rejection image(const LocalChange& c, LocalChange& m) noexcept
    {
        m.clear();
        // Whatever c's operator read, the image's reads the mirrored nodes: claim them all first.
        const size_t held = claims_.held().size();
        for (size_t i = 0; i < held; ++i)
        {
            const Vertex v = claims_.held()[i];
            if (mesh_.is_deleted(v))
                continue;
            const Vertex w = image_of(v);
            if (!w.is_valid())
                return Rejection::Topology;
            if (!claims_.take(w))
                return Rejection::Busy;
            if (mesh_.position(w) != reflect(mesh_.position(v))) // moved before it was claimed
                return Rejection::Busy;
        }
        for (Vertex v : c.removed_nodes())
            m.remove_node(image_of(v));
        for (Edge e : c.removed_struts())
        {
            const Halfedge h = mesh_.find_halfedge(image_of(mesh_.vertex(e, 0)), image_of(mesh_.vertex(e, 1)));
            if (!h.is_valid())
                return Rejection::Topology;
            m.remove_strut(ZomeMesh::edge(h));
        }
        for (Face f : c.removed_faces())
        {
            // Reflection turns the face over: its halfedge a → b becomes b' → a' of the image.
            const Halfedge h = mesh_.halfedge(f);
            const Halfedge g = mesh_.find_halfedge(image_of(mesh_.to_vertex(h)), image_of(mesh_.from_vertex(h)));
            if (!g.is_valid() || mesh_.is_boundary(g))
                return Rejection::Topology;
            m.remove_face(mesh_.face(g));
        }
        for (const ZVec& p : c.added_nodes())
            m.add_node(reflect(p));
        for (const NewStrut& s : c.added_struts())
            m.add_strut(reflect(s.a), reflect(s.b));
        for (const NewFace& f : c.added_faces())
        {
            std::array<ZVec, 4> corners;
            for (size_t i = 0; i < f.size; ++i)
                corners[i] = reflect(f.corners[f.size - 1 - i]); // reversed: the image keeps its outside out
            m.add_face(std::span<const ZVec>(corners.data(), f.size));
        }
        return m.overflowed() || overflowed_ ? Rejection::Overflow : Rejection::None;
    }

    // Whether c and its image m can be applied together (c and m each valid on their own).
    Rejection compatible(const LocalChange& c, const LocalChange& m) const noexcept
    {
        for (Vertex v : m.removed_nodes())
            if (contains(c.removed_nodes(), v))
                return Rejection::MirrorOverlap;
        for (Edge e : m.removed_struts())
            if (contains(c.removed_struts(), e))
                return Rejection::MirrorOverlap;
        for (Face f : m.removed_faces())
            if (contains(c.removed_faces(), f))
                return Rejection::MirrorOverlap;
        for (const ZVec& p : m.added_nodes())
            if (contains(c.added_nodes(), p))
                return Rejection::MirrorOverlap;
        // A new strut is a chord of its own change's hole: one both add would get four faces.
        for (const NewStrut& s : m.added_struts())
            for (const NewStrut& t : c.added_struts())
                if (same_strut(s, t))
                    return Rejection::MirrorOverlap;
        if (const Rejection r = shared_nodes_ok(c, m); r != Rejection::None)
            return r;
        if (folds(c, m) || folds(m, c))
            return Rejection::FoldedQuad;
        return Rejection::None;
    }

private:
    // Beyond int32 no node can be there: the change is then refused (image() reports Overflow), never
    // taken for its own image.
    ZVec reflect(const ZVec& p) const noexcept
    {
        try
        {
            return mirror_.reflect(p);
        }
        catch (const std::exception&)
        {
            overflowed_ = true;
            return p;
        }
    }

    Vertex image_of(Vertex v) const noexcept
    {
        const Vertex w = mesh_.find_vertex(reflect(mesh_.position(v)));
        return w;
    }

    // At a surviving node where both changes add struts: no two new struts in one slot, and at
    // least three struts left.
    Rejection shared_nodes_ok(const LocalChange& c, const LocalChange& m) const noexcept
    {
        for (const NewStrut& s : c.added_struts())
            for (const ZVec& w : {s.a, s.b})
            {
                const ZVec& other = w == s.a ? s.b : s.a;
                for (const NewStrut& t : m.added_struts())
                {
                    if (t.a != w && t.b != w)
                        continue;
                    const ZVec& other_t = t.a == w ? t.b : t.a;
                    if (slot_of(other - w) == slot_of(other_t - w))
                        return Rejection::SlotConflict;
                }
            }
        // Valence: a node both changes remove struts at.
        for (Edge e : c.removed_struts())
            for (int i = 0; i < 2; ++i)
            {
                const Vertex w = mesh_.vertex(e, i);
                if (contains(c.removed_nodes(), w) || contains(m.removed_nodes(), w) || !touches(m, w))
                    continue;
                if (valence_after(c, m, w) < 3)
                    return Rejection::Valence;
            }
        return Rejection::None;
    }

    bool touches(const LocalChange& m, Vertex w) const noexcept
    {
        for (Edge e : m.removed_struts())
            if (mesh_.vertex(e, 0) == w || mesh_.vertex(e, 1) == w)
                return true;
        return false;
    }

    long valence_after(const LocalChange& c, const LocalChange& m, Vertex w) const noexcept
    {
        long k = static_cast<long>(mesh_.valence(w));
        const ZVec& p = mesh_.position(w);
        for (const LocalChange* x : {&c, &m})
        {
            for (Edge e : x->removed_struts())
                if (mesh_.vertex(e, 0) == w || mesh_.vertex(e, 1) == w)
                    --k;
            for (const NewStrut& s : x->added_struts())
                if (s.a == p || s.b == p)
                    ++k;
        }
        return k;
    }

    // Whether a new quad of `a` has a new strut of `b` as a diagonal.
    static bool folds(const LocalChange& a, const LocalChange& b) noexcept
    {
        for (const NewFace& f : a.added_faces())
        {
            if (f.size != 4)
                continue;
            for (const NewStrut& s : b.added_struts())
                for (int d = 0; d < 2; ++d)
                    if (same_strut(s, {f.corners[d], f.corners[d + 2]}))
                        return true;
        }
        return false;
    }

    const ZomeMesh& mesh_;
    const LatticeMirror& mirror_;
    Claims& claims_;
    mutable bool overflowed_ = false;
};

// Appends m to c.
bool append(LocalChange& c, const LocalChange& m) noexcept
{
    bool ok = true;
    for (Vertex v : m.removed_nodes())
        ok = c.remove_node(v) && ok;
    for (Edge e : m.removed_struts())
        ok = c.remove_strut(e) && ok;
    for (Face f : m.removed_faces())
        ok = c.remove_face(f) && ok;
    for (const ZVec& p : m.added_nodes())
        ok = c.add_node(p) && ok;
    for (const NewStrut& s : m.added_struts())
        ok = c.add_strut(s.a, s.b) && ok;
    for (const NewFace& f : m.added_faces())
        ok = c.add_face(f.view()) && ok;
    return ok;
}

} // namespace

Rejection mirror_proposal(const ZomeMesh& mesh, const LatticeMirror& mirror, Claims& claims,
                          Proposal& proposal) noexcept
{
    thread_local LocalChange image;
    Mirroring mirroring(mesh, mirror, claims);
    LocalChange& c = proposal.change;
    if (const Rejection r = mirroring.image(c, image); r != Rejection::None)
        return r;
    // Its own mirror image: nothing to add.
    if (same_set(c.removed_faces(), image.removed_faces()) && same_set(c.removed_nodes(), image.removed_nodes()) &&
        same_set(c.added_nodes(), image.added_nodes()) && same_face_set(c, image))
        return Rejection::None;
    if (const Rejection r = mirroring.compatible(c, image); r != Rejection::None)
        return r;
    return append(c, image) ? Rejection::None : Rejection::Overflow;
}

} // namespace zomeify
