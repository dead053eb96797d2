#include "core/anneal/energy/local_change.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "core/mesh/circulators.h"

namespace zomeify {

void LocalChange::clear() noexcept
{
    removed_nodes_.clear();
    removed_struts_.clear();
    removed_faces_.clear();
    added_nodes_.clear();
    added_struts_.clear();
    added_faces_.clear();
    bad_face_ = false;
}

bool LocalChange::remove_star(const ZomeMesh& mesh, Vertex v) noexcept
{
    bool ok = remove_node(v);
    for (Halfedge h : outgoing_halfedges(mesh, v))
    {
        ok = remove_strut(ZomeMesh::edge(h)) && ok;
        if (!mesh.is_boundary(h))
        {
            ok = remove_face(mesh.face(h)) && ok;
        }
    }
    return ok;
}

bool LocalChange::add_face(std::span<const ZVec> corners) noexcept
{
    if (corners.size() < 3 || corners.size() > 4)
    {
        bad_face_ = true;
        return false;
    }
    NewFace f;
    f.size = static_cast<uint8_t>(corners.size());
    std::copy(corners.begin(), corners.end(), f.corners.begin());
    return added_faces_.push_back(f);
}

bool LocalChange::add_triangle(const ZVec& a, const ZVec& b, const ZVec& c) noexcept
{
    const std::array<ZVec, 3> corners{a, b, c};
    return add_face(corners);
}

bool LocalChange::add_quad(const ZVec& a, const ZVec& b, const ZVec& c, const ZVec& d) noexcept
{
    const std::array<ZVec, 4> corners{a, b, c, d};
    return add_face(corners);
}

bool LocalChange::overflowed() const noexcept
{
    return bad_face_ || removed_nodes_.overflowed() || removed_struts_.overflowed() || removed_faces_.overflowed() ||
           added_nodes_.overflowed() || added_struts_.overflowed() || added_faces_.overflowed();
}

namespace {

template <class List, class T>
bool contains(const List& list, const T& x)
{
    return std::find(list.begin(), list.end(), x) != list.end();
}

template <class List>
bool has_duplicates(const List& list)
{
    for (size_t i = 0; i < list.size(); ++i)
    {
        for (size_t j = i + 1; j < list.size(); ++j)
        {
            if (list[i] == list[j])
            {
                return true;
            }
        }
    }
    return false;
}

} // namespace

std::string check_change(const ZomeMesh& mesh, const LocalChange& change)
{
    std::ostringstream msg;
    if (change.overflowed())
    {
        return "a list of the change overflowed (or a face had not 3 or 4 corners)";
    }
    if (has_duplicates(change.removed_nodes()) || has_duplicates(change.removed_struts()) ||
        has_duplicates(change.removed_faces()))
    {
        return "an element is removed twice";
    }
    for (Vertex v : change.removed_nodes())
    {
        if (!mesh.is_valid(v))
        {
            msg << "removed node " << v << " is not a live node";
            return msg.str();
        }
        for (Halfedge h : outgoing_halfedges(mesh, v))
        {
            if (!contains(change.removed_struts(), ZomeMesh::edge(h)))
            {
                msg << "removed node " << v << " keeps strut " << ZomeMesh::edge(h);
                return msg.str();
            }
            if (!mesh.is_boundary(h) && !contains(change.removed_faces(), mesh.face(h)))
            {
                msg << "removed node " << v << " keeps face " << mesh.face(h);
                return msg.str();
            }
        }
    }
    for (Edge e : change.removed_struts())
    {
        if (!mesh.is_valid(e))
        {
            msg << "removed strut " << e << " is not a live edge";
            return msg.str();
        }
        for (int side = 0; side < 2; ++side)
        {
            const Face f = mesh.face(ZomeMesh::halfedge(e, side));
            if (f.is_valid() && !contains(change.removed_faces(), f))
            {
                msg << "removed strut " << e << " keeps face " << f;
                return msg.str();
            }
        }
    }
    // Positions that new elements may use: added nodes, and surviving nodes on the removed region.
    std::vector<ZVec> usable(change.added_nodes().begin(), change.added_nodes().end());
    auto add_existing = [&](Vertex v) {
        if (!contains(change.removed_nodes(), v))
        {
            usable.push_back(mesh.position(v));
        }
    };
    for (Face f : change.removed_faces())
    {
        if (!mesh.is_valid(f))
        {
            msg << "removed face " << f << " is not a live face";
            return msg.str();
        }
        for (Vertex v : face_vertices(mesh, f))
        {
            add_existing(v);
        }
    }
    for (Edge e : change.removed_struts())
    {
        add_existing(mesh.vertex(e, 0));
        add_existing(mesh.vertex(e, 1));
    }
    for (const NewStrut& s : change.added_struts())
    {
        if (!contains(usable, s.a) || !contains(usable, s.b))
        {
            msg << "added strut " << s.a << " – " << s.b << " ends at an unknown node";
            return msg.str();
        }
    }
    for (const NewFace& f : change.added_faces())
    {
        for (const ZVec& p : f.view())
        {
            if (!contains(usable, p))
            {
                msg << "added face corner " << p << " is not a known node";
                return msg.str();
            }
        }
    }
    return {};
}

} // namespace zomeify
