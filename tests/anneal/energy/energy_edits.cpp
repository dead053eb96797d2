#include "tests/anneal/energy/energy_edits.h"

#include <algorithm>
#include <vector>

#include "core/mesh/circulators.h"
#include "core/zome/slots.h"

namespace zomeify::test {

namespace {

template <class H>
H random_element(const ZomeMesh& mesh, size_t size, EditRng& rng)
{
    // rng() % size rather than a std distribution: the same sequence with libstdc++ and libc++,
    // so native and wasm runs draw the same edits.
    for (int tries = 0; tries < 64; ++tries)
    {
        const H h(static_cast<MeshIndex>(rng() % size));
        if (!mesh.is_deleted(h))
        {
            return h;
        }
    }
    return H();
}

std::vector<Vertex> corners_of(const ZomeMesh& mesh, Face f)
{
    std::vector<Vertex> out;
    for (Vertex v : face_vertices(mesh, f))
    {
        out.push_back(v);
    }
    return out;
}

} // namespace

std::optional<Edit> add_diagonal(const ZomeMesh& mesh, EditRng& rng)
{
    const Face f = random_element<Face>(mesh, mesh.faces_size(), rng);
    if (!f.is_valid() || mesh.valence(f) != 4)
    {
        return std::nullopt;
    }
    const std::vector<Vertex> q = corners_of(mesh, f);
    const size_t i = rng() % 2;
    const Vertex a = q[i], b = q[i + 1], c = q[i + 2], d = q[(i + 3) % 4];
    if (!mesh.is_split_ok(f, a, c))
    {
        return std::nullopt;
    }
    Edit e;
    e.kind = "add_diagonal";
    const auto& p = mesh.positions();
    e.change.remove_face(f);
    e.change.add_strut(p[a], p[c]);
    e.change.add_triangle(p[a], p[b], p[c]);
    e.change.add_triangle(p[c], p[d], p[a]);
    e.apply = [f, a, c](ZomeMesh& m) { m.split_face(f, a, c); };
    return e;
}

namespace {

// The two triangles of an edge u–v and their apexes: face(h) = (u, v, x), face(opposite h) = (v, u, y).
struct Diamond
{
    Edge edge;
    Vertex u, v, x, y;
};

std::optional<Diamond> diamond(const ZomeMesh& mesh, EditRng& rng)
{
    const Edge e = random_element<Edge>(mesh, mesh.edges_size(), rng);
    if (!e.is_valid() || !mesh.is_remove_edge_ok(e))
    {
        return std::nullopt;
    }
    const Halfedge h = ZomeMesh::halfedge(e, 0);
    const Halfedge o = ZomeMesh::opposite(h);
    if (mesh.valence(mesh.face(h)) != 3 || mesh.valence(mesh.face(o)) != 3)
    {
        return std::nullopt;
    }
    Diamond d{e, mesh.from_vertex(h), mesh.to_vertex(h), mesh.to_vertex(mesh.next(h)), mesh.to_vertex(mesh.next(o))};
    // Both ends keep at least three struts; the merged quad has four distinct corners.
    if (d.x == d.y || mesh.valence(d.u) < 4 || mesh.valence(d.v) < 4)
    {
        return std::nullopt;
    }
    return d;
}

void remove_diamond(const ZomeMesh& mesh, const Diamond& d, LocalChange& change)
{
    const Halfedge h = ZomeMesh::halfedge(d.edge, 0);
    change.remove_strut(d.edge);
    change.remove_face(mesh.face(h));
    change.remove_face(mesh.face(ZomeMesh::opposite(h)));
}

} // namespace

std::optional<Edit> remove_diagonal(const ZomeMesh& mesh, EditRng& rng)
{
    const std::optional<Diamond> d = diamond(mesh, rng);
    if (!d)
    {
        return std::nullopt;
    }
    Edit e;
    e.kind = "remove_diagonal";
    const auto& p = mesh.positions();
    remove_diamond(mesh, *d, e.change);
    e.change.add_quad(p[d->v], p[d->x], p[d->u], p[d->y]);
    e.apply = [edge = d->edge](ZomeMesh& m) { m.remove_edge(edge); };
    return e;
}

std::optional<Edit> flip_diagonal(const ZomeMesh& mesh, EditRng& rng)
{
    const std::optional<Diamond> d = diamond(mesh, rng);
    if (!d || mesh.find_edge(d->x, d->y).is_valid())
    {
        return std::nullopt;
    }
    Edit e;
    e.kind = "flip_diagonal";
    const auto& p = mesh.positions();
    remove_diamond(mesh, *d, e.change);
    e.change.add_strut(p[d->x], p[d->y]);
    e.change.add_triangle(p[d->x], p[d->u], p[d->y]);
    e.change.add_triangle(p[d->y], p[d->v], p[d->x]);
    e.apply = [dd = *d](ZomeMesh& m) {
        const Face f = m.remove_edge(dd.edge);
        m.split_face(f, dd.x, dd.y);
    };
    return e;
}

// Prefers vectors that keep every strut a Zome vector; any free position otherwise.
std::optional<Edit> move_node(const ZomeMesh& mesh, EditRng& rng)
{
    const Vertex v = random_element<Vertex>(mesh, mesh.vertices_size(), rng);
    if (!v.is_valid())
    {
        return std::nullopt;
    }
    const ZVec from = mesh.position(v);
    std::vector<ZVec> zome_keeping, free;
    for (const ZVec& z : zome_vectors())
    {
        const ZVec to = from + z;
        if (!mesh.is_position_free(to))
        {
            continue;
        }
        free.push_back(to);
        bool keeps = true;
        for (Vertex w : adjacent_vertices(mesh, v))
        {
            keeps = keeps && vector_id_of(mesh.position(w) - to) >= 0;
        }
        if (keeps)
        {
            zome_keeping.push_back(to);
        }
    }
    const std::vector<ZVec>& choices = zome_keeping.empty() ? free : zome_keeping;
    if (choices.empty())
    {
        return std::nullopt;
    }
    const ZVec to = choices[rng() % choices.size()];
    Edit e;
    e.kind = "move_node";
    e.change.remove_star(mesh, v);
    e.change.add_node(to);
    for (Vertex w : adjacent_vertices(mesh, v))
    {
        e.change.add_strut(to, mesh.position(w));
    }
    for (Face f : incident_faces(mesh, v))
    {
        std::vector<ZVec> corners;
        for (Vertex c : face_vertices(mesh, f))
        {
            corners.push_back(c == v ? to : mesh.position(c));
        }
        e.change.add_face(corners);
    }
    e.apply = [v, to](ZomeMesh& m) { m.move_vertex(v, to); };
    return e;
}

std::optional<Edit> insert_node(const ZomeMesh& mesh, EditRng& rng)
{
    const Face f = random_element<Face>(mesh, mesh.faces_size(), rng);
    if (!f.is_valid())
    {
        return std::nullopt;
    }
    const std::vector<Vertex> c = corners_of(mesh, f);
    const int k = static_cast<int>(c.size());
    ZVec sum;
    for (Vertex v : c)
    {
        sum += mesh.position(v);
    }
    ZVec p;
    for (int i = 0; i < 6; ++i)
    {
        if (sum.c[i] % k != 0)
        {
            return std::nullopt;
        }
        p.c[i] = sum.c[i] / k;
    }
    if (rng() % 2 == 0)
    {
        p += zome_vector(static_cast<int>(rng() % kSlotCount) * kSizeCount); // a b0/y0/r0 vector
    }
    if (!mesh.is_position_free(p))
    {
        return std::nullopt;
    }
    Edit e;
    e.kind = "insert_node";
    e.change.remove_face(f);
    e.change.add_node(p);
    for (int i = 0; i < k; ++i)
    {
        e.change.add_strut(mesh.position(c[i]), p);
        e.change.add_triangle(mesh.position(c[i]), mesh.position(c[(i + 1) % k]), p);
    }
    e.apply = [f, c, p](ZomeMesh& m) {
        m.remove_face(f);
        const Vertex n = m.add_vertex(p);
        for (size_t i = 0; i < c.size(); ++i)
        {
            m.add_triangle(c[i], c[(i + 1) % c.size()], n);
        }
    };
    return e;
}

std::optional<Edit> remove_node(const ZomeMesh& mesh, EditRng& rng)
{
    const Vertex v = random_element<Vertex>(mesh, mesh.vertices_size(), rng);
    if (!v.is_valid())
    {
        return std::nullopt;
    }
    std::vector<Vertex> link;
    std::vector<Face> outer;
    for (Halfedge h : outgoing_halfedges(mesh, v))
    {
        if (mesh.valence(mesh.face(h)) != 3 || mesh.valence(mesh.to_vertex(h)) < 4)
        {
            return std::nullopt;
        }
        link.push_back(mesh.to_vertex(h));
        outer.push_back(mesh.face(ZomeMesh::opposite(mesh.next(h))));
    }
    if (link.size() < 3 || link.size() > 4)
    {
        return std::nullopt;
    }
    // The link polygon must not already bound a face on its other side (a tetrahedron).
    if (std::all_of(outer.begin(), outer.end(), [&](Face g) { return g == outer[0]; }))
    {
        return std::nullopt;
    }
    Edit e;
    e.kind = "remove_node";
    e.change.remove_star(mesh, v);
    std::vector<ZVec> corners;
    for (Vertex w : link)
    {
        corners.push_back(mesh.position(w));
    }
    e.change.add_face(corners);
    e.apply = [v, link](ZomeMesh& m) {
        m.remove_vertex(v);
        m.add_face(link);
    };
    return e;
}

namespace {

using Proposer = std::optional<Edit> (*)(const ZomeMesh&, EditRng&);
constexpr Proposer kProposers[] = {add_diagonal, remove_diagonal, flip_diagonal, move_node, insert_node, remove_node};

} // namespace

std::optional<Edit> random_edit(const ZomeMesh& mesh, EditRng& rng)
{
    for (int tries = 0; tries < 100; ++tries)
    {
        if (std::optional<Edit> e = kProposers[rng() % std::size(kProposers)](mesh, rng))
        {
            return e;
        }
    }
    return std::nullopt;
}

} // namespace zomeify::test
