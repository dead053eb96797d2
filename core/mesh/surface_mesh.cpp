#include "core/mesh/surface_mesh.h"

#include <string>
#include <unordered_map>
#include <utility>

#include "core/mesh/small_buffer.h"
#include "core/mesh/topology_error.h"

namespace zomeify {

namespace {

// Faces of a Zome surface have 3 or 4 corners and nodes rarely exceed valence 12, so 16 inline
// entries keep every realistic edit off the heap.
constexpr size_t kInline = 16;
using HalfedgeBuffer = detail::SmallBuffer<Halfedge, kInline>;
using VertexBuffer = detail::SmallBuffer<Vertex, kInline>;
using FaceBuffer = detail::SmallBuffer<Face, kInline>;

uint64_t directed_key(MeshIndex a, MeshIndex b) { return (static_cast<uint64_t>(a) << 32) | b; }

} // namespace

const char* to_string(AddFaceStatus status)
{
    switch (status)
    {
    case AddFaceStatus::Ok:
        return "ok";
    case AddFaceStatus::TooFewVertices:
        return "a face needs at least three vertices";
    case AddFaceStatus::InvalidVertex:
        return "a face vertex is out of range or deleted";
    case AddFaceStatus::RepeatedVertex:
        return "a vertex occurs twice in the face";
    case AddFaceStatus::ComplexVertex:
        return "a face vertex is already surrounded by faces (non-manifold vertex)";
    case AddFaceStatus::ComplexEdge:
        return "a face edge already has a face on this side (non-manifold edge or flipped face)";
    case AddFaceStatus::RelinkFailed:
        return "the faces around a vertex cannot be ordered into one disc";
    }
    return "unknown";
}

SurfaceMesh::SurfaceMesh() { add_builtin_properties(); }

SurfaceMesh::SurfaceMesh(const SurfaceMesh& other)
    : vprops_(other.vprops_), hprops_(other.hprops_), eprops_(other.eprops_), fprops_(other.fprops_),
      deleted_vertices_(other.deleted_vertices_), deleted_edges_(other.deleted_edges_),
      deleted_faces_(other.deleted_faces_), slot_reuse_(other.slot_reuse_), free_edges_(other.free_edges_),
      free_faces_(other.free_faces_)
{
    bind_builtin_properties();
}

SurfaceMesh& SurfaceMesh::operator=(const SurfaceMesh& other)
{
    if (this == &other)
        return *this;
    vprops_ = other.vprops_;
    hprops_ = other.hprops_;
    eprops_ = other.eprops_;
    fprops_ = other.fprops_;
    deleted_vertices_ = other.deleted_vertices_;
    deleted_edges_ = other.deleted_edges_;
    deleted_faces_ = other.deleted_faces_;
    slot_reuse_ = other.slot_reuse_;
    free_edges_ = other.free_edges_;
    free_faces_ = other.free_faces_;
    bind_builtin_properties();
    return *this;
}

// Moving the containers moves the owning pointers, so the property handles stay valid.
SurfaceMesh::SurfaceMesh(SurfaceMesh&& other) noexcept = default;
SurfaceMesh& SurfaceMesh::operator=(SurfaceMesh&& other) noexcept = default;

void SurfaceMesh::add_builtin_properties()
{
    vout_ = VertexProperty<Halfedge>(vprops_.add<Halfedge>("v:connectivity"));
    vdeleted_ = VertexProperty<uint8_t>(vprops_.add<uint8_t>("v:deleted", 0));
    links_ = HalfedgeProperty<HalfedgeLinks>(hprops_.add<HalfedgeLinks>("h:links"));
    edeleted_ = EdgeProperty<uint8_t>(eprops_.add<uint8_t>("e:deleted", 0));
    fhalf_ = FaceProperty<Halfedge>(fprops_.add<Halfedge>("f:connectivity"));
    fdeleted_ = FaceProperty<uint8_t>(fprops_.add<uint8_t>("f:deleted", 0));
}

void SurfaceMesh::bind_builtin_properties()
{
    vout_ = VertexProperty<Halfedge>(vprops_.get<Halfedge>("v:connectivity"));
    vdeleted_ = VertexProperty<uint8_t>(vprops_.get<uint8_t>("v:deleted"));
    links_ = HalfedgeProperty<HalfedgeLinks>(hprops_.get<HalfedgeLinks>("h:links"));
    edeleted_ = EdgeProperty<uint8_t>(eprops_.get<uint8_t>("e:deleted"));
    fhalf_ = FaceProperty<Halfedge>(fprops_.get<Halfedge>("f:connectivity"));
    fdeleted_ = FaceProperty<uint8_t>(fprops_.get<uint8_t>("f:deleted"));
}

bool SurfaceMesh::is_boundary(Face f) const
{
    const Halfedge start = halfedge(f);
    Halfedge h = start;
    do
    {
        if (is_boundary(opposite(h)))
            return true;
        h = next(h);
    } while (h != start);
    return false;
}

Halfedge SurfaceMesh::find_halfedge(Vertex from, Vertex to) const
{
    const Halfedge start = halfedge(from);
    if (!start.is_valid())
        return {};
    Halfedge h = start;
    do
    {
        if (to_vertex(h) == to)
            return h;
        h = ccw_rotated(h);
    } while (h != start);
    return {};
}

Edge SurfaceMesh::find_edge(Vertex a, Vertex b) const
{
    const Halfedge h = find_halfedge(a, b);
    return h.is_valid() ? edge(h) : Edge();
}

size_t SurfaceMesh::valence(Vertex v) const
{
    const Halfedge start = halfedge(v);
    if (!start.is_valid())
        return 0;
    size_t n = 0;
    Halfedge h = start;
    do
    {
        ++n;
        h = ccw_rotated(h);
    } while (h != start);
    return n;
}

size_t SurfaceMesh::valence(Face f) const
{
    const Halfedge start = halfedge(f);
    size_t n = 0;
    Halfedge h = start;
    do
    {
        ++n;
        h = next(h);
    } while (h != start);
    return n;
}

Vertex SurfaceMesh::new_vertex()
{
    vprops_.push_back();
    return Vertex(static_cast<MeshIndex>(vertices_size() - 1));
}

Vertex SurfaceMesh::add_vertex()
{
    const Vertex v = new_vertex();
    notify_vertex_added(v);
    return v;
}

void SurfaceMesh::set_slot_reuse(bool on)
{
    slot_reuse_ = on;
    if (!on)
    {
        free_edges_.clear();
        free_faces_.clear();
    }
}

void SurfaceMesh::free_edge_slot(Edge e)
{
    edeleted_[e] = 1;
    ++deleted_edges_;
    if (slot_reuse_)
        free_edges_.push_back(e.idx());
}

void SurfaceMesh::free_face_slot(Face f)
{
    fdeleted_[f] = 1;
    ++deleted_faces_;
    if (slot_reuse_)
        free_faces_.push_back(f.idx());
}

Halfedge SurfaceMesh::new_edge(Vertex a, Vertex b)
{
    Edge e;
    if (!free_edges_.empty())
    {
        // Every property back to its default, the deleted flag included.
        e = Edge(free_edges_.back());
        free_edges_.pop_back();
        eprops_.reset(e.idx());
        hprops_.reset(2 * static_cast<size_t>(e.idx()));
        hprops_.reset(2 * static_cast<size_t>(e.idx()) + 1);
        --deleted_edges_;
    }
    else
    {
        eprops_.push_back();
        hprops_.push_back();
        hprops_.push_back();
        e = Edge(static_cast<MeshIndex>(edges_size() - 1));
    }
    const Halfedge h = halfedge(e, 0);
    links_[h] = HalfedgeLinks{b, Halfedge(), Halfedge(), Face()};
    links_[opposite(h)] = HalfedgeLinks{a, Halfedge(), Halfedge(), Face()};
    on_edge_added(e);
    if (observer_)
        observer_->edge_added(e);
    return h;
}

Face SurfaceMesh::new_face()
{
    if (!free_faces_.empty())
    {
        const Face f(free_faces_.back());
        free_faces_.pop_back();
        fprops_.reset(f.idx());
        --deleted_faces_;
        return f;
    }
    fprops_.push_back();
    return Face(static_cast<MeshIndex>(faces_size() - 1));
}

namespace {

// Walks clockwise around the vertex that inner_next leaves, starting behind inner_next's fan,
// to the first boundary gap other than inner_prev's: the place where the fans lying between
// inner_prev and inner_next (the "patch") can be moved so that the new face fits between them.
Halfedge find_free_gap(const SurfaceMesh& m, Halfedge inner_prev, Halfedge inner_next)
{
    const Halfedge outer_prev = SurfaceMesh::opposite(inner_next);
    Halfedge h = outer_prev;
    do
    {
        h = SurfaceMesh::opposite(m.next(h));
        if (m.is_boundary(h) && h != inner_prev)
            return h;
    } while (h != outer_prev);
    return {};
}

} // namespace

AddFaceStatus SurfaceMesh::check_add_face(std::span<const Vertex> vertices) const
{
    const size_t n = vertices.size();
    if (n < 3)
        return AddFaceStatus::TooFewVertices;
    for (size_t i = 0; i < n; ++i)
    {
        if (!is_valid(vertices[i]))
            return AddFaceStatus::InvalidVertex;
        for (size_t j = 0; j < i; ++j)
            if (vertices[j] == vertices[i])
                return AddFaceStatus::RepeatedVertex;
    }
    for (size_t i = 0; i < n; ++i)
        if (!is_boundary(vertices[i]))
            return AddFaceStatus::ComplexVertex;
    HalfedgeBuffer hs;
    hs.resize(n);
    for (size_t i = 0; i < n; ++i)
    {
        hs[i] = find_halfedge(vertices[i], vertices[(i + 1) % n]);
        if (hs[i].is_valid() && !is_boundary(hs[i]))
            return AddFaceStatus::ComplexEdge;
    }
    // Relinking only rewires halfedges entering one vertex, so each corner can be checked on the
    // unmodified mesh independently of the others.
    for (size_t i = 0; i < n; ++i)
    {
        const Halfedge inner_prev = hs[i];
        const Halfedge inner_next = hs[(i + 1) % n];
        if (inner_prev.is_valid() && inner_next.is_valid() && next(inner_prev) != inner_next &&
            !find_free_gap(*this, inner_prev, inner_next).is_valid())
            return AddFaceStatus::RelinkFailed;
    }
    return AddFaceStatus::Ok;
}

Face SurfaceMesh::add_face(std::span<const Vertex> vertices)
{
    const AddFaceStatus status = check_add_face(vertices);
    if (status != AddFaceStatus::Ok)
    {
        std::string msg = "add_face(";
        for (size_t i = 0; i < vertices.size(); ++i)
            msg += (i ? " v" : "v") + std::to_string(vertices[i].idx());
        throw TopologyError(msg + "): " + to_string(status));
    }
    return try_add_face(vertices);
}

Face SurfaceMesh::try_add_face(std::span<const Vertex> vertices)
{
    if (check_add_face(vertices) != AddFaceStatus::Ok)
        return {};
    const size_t n = vertices.size();
    HalfedgeBuffer hs;
    hs.resize(n);
    detail::SmallBuffer<uint8_t, kInline> is_new;
    is_new.resize(n);
    for (size_t i = 0; i < n; ++i)
    {
        hs[i] = find_halfedge(vertices[i], vertices[(i + 1) % n]);
        is_new[i] = !hs[i].is_valid();
    }

    // Make consecutive existing halfedges neighbours in their boundary cycle by moving the patch
    // of fans between them into another gap of the shared vertex.
    for (size_t i = 0; i < n; ++i)
    {
        const size_t ii = (i + 1) % n;
        if (is_new[i] || is_new[ii])
            continue;
        const Halfedge inner_prev = hs[i];
        const Halfedge inner_next = hs[ii];
        if (next(inner_prev) == inner_next)
            continue;
        const Halfedge boundary_prev = find_free_gap(*this, inner_prev, inner_next);
        const Halfedge boundary_next = next(boundary_prev);
        const Halfedge patch_start = next(inner_prev);
        const Halfedge patch_end = prev(inner_next);
        set_next(boundary_prev, patch_start);
        set_next(patch_end, boundary_next);
        set_next(inner_prev, inner_next);
    }

    for (size_t i = 0; i < n; ++i)
        if (is_new[i])
            hs[i] = new_edge(vertices[i], vertices[(i + 1) % n]);

    const Face f = new_face();
    fhalf_[f] = hs[n - 1];

    // The new next-links are collected first and applied afterwards, so that every corner reads
    // the boundary cycles as they were before this face.
    detail::SmallBuffer<std::pair<Halfedge, Halfedge>, 3 * kInline> links;
    VertexBuffer to_adjust;
    for (size_t i = 0; i < n; ++i)
    {
        const size_t ii = (i + 1) % n;
        const Vertex v = vertices[ii];
        const Halfedge inner_prev = hs[i];
        const Halfedge inner_next = hs[ii];
        const Halfedge outer_prev = opposite(inner_next);
        const Halfedge outer_next = opposite(inner_prev);
        const int kind = (is_new[i] ? 1 : 0) | (is_new[ii] ? 2 : 0);
        if (kind == 1)
        {
            // Entering edge new, leaving edge old: splice the new outer side in before inner_next.
            links.push_back({prev(inner_next), outer_next});
            vout_[v] = outer_next;
        }
        else if (kind == 2)
        {
            links.push_back({outer_prev, next(inner_prev)});
            vout_[v] = next(inner_prev);
        }
        else if (kind == 3)
        {
            if (is_isolated(v))
            {
                vout_[v] = outer_next;
                links.push_back({outer_prev, outer_next});
            }
            else
            {
                const Halfedge boundary_next = halfedge(v);
                links.push_back({prev(boundary_next), outer_next});
                links.push_back({outer_prev, boundary_next});
            }
        }
        else if (halfedge(v) == inner_next)
            to_adjust.push_back(v);
        if (kind != 0)
            links.push_back({inner_prev, inner_next});
        links_[inner_prev].face = f;
    }
    for (const auto& [h, nh] : links)
        set_next(h, nh);
    for (Vertex v : to_adjust)
        adjust_outgoing_halfedge(v);
    if (observer_)
        observer_->face_added(f);
    return f;
}

Face SurfaceMesh::add_triangle(Vertex a, Vertex b, Vertex c)
{
    const Vertex vs[3] = {a, b, c};
    return add_face(vs);
}

Face SurfaceMesh::add_quad(Vertex a, Vertex b, Vertex c, Vertex d)
{
    const Vertex vs[4] = {a, b, c, d};
    return add_face(vs);
}

void SurfaceMesh::adjust_outgoing_halfedge(Vertex v)
{
    const Halfedge start = halfedge(v);
    if (!start.is_valid())
        return;
    Halfedge h = start;
    do
    {
        if (is_boundary(h))
        {
            vout_[v] = h;
            return;
        }
        h = ccw_rotated(h);
    } while (h != start);
}

void SurfaceMesh::remove_boundary_edge(Edge e)
{
    if (observer_)
        observer_->edge_removing(e);
    const Halfedge h = halfedge(e, 0);
    const Halfedge o = halfedge(e, 1);
    const Halfedge a = prev(h), b = next(h), c = prev(o), d = next(o);
    const Vertex vh = to_vertex(h), vo = to_vertex(o);
    // At vh the cycle ran c → o … h → b; without the edge it runs c → b.
    if (b == o)
        vout_[vh] = Halfedge();
    else
    {
        set_next(c, b);
        if (vout_[vh] == o)
            vout_[vh] = b;
    }
    if (d == h)
        vout_[vo] = Halfedge();
    else
    {
        set_next(a, d);
        if (vout_[vo] == h)
            vout_[vo] = d;
    }
    free_edge_slot(e);
}

void SurfaceMesh::remove_face(Face f)
{
    if (!is_valid(f))
        throw TopologyError("remove_face: invalid or deleted face");
    if (observer_)
        observer_->face_removing(f);
    HalfedgeBuffer hs;
    VertexBuffer vs;
    const Halfedge start = halfedge(f);
    Halfedge h = start;
    do
    {
        hs.push_back(h);
        vs.push_back(to_vertex(h));
        links_[h].face = Face();
        h = next(h);
    } while (h != start);
    free_face_slot(f);
    for (Halfedge x : hs)
        if (is_boundary(opposite(x)))
            remove_boundary_edge(edge(x));
    for (Vertex v : vs)
        adjust_outgoing_halfedge(v);
}

void SurfaceMesh::delete_vertex_flag(Vertex v)
{
    if (observer_)
        observer_->vertex_removing(v);
    on_vertex_removing(v);
    vdeleted_[v] = 1;
    vout_[v] = Halfedge();
    ++deleted_vertices_;
}

void SurfaceMesh::remove_vertex(Vertex v)
{
    if (!is_valid(v))
        throw TopologyError("remove_vertex: invalid or deleted vertex");
    FaceBuffer fs;
    const Halfedge start = halfedge(v);
    if (start.is_valid())
    {
        Halfedge h = start;
        do
        {
            if (!is_boundary(h))
                fs.push_back(face(h));
            h = ccw_rotated(h);
        } while (h != start);
    }
    for (Face f : fs)
        remove_face(f);
    // A vertex with a dangling edge (no face on either side) cannot arise from the primitives,
    // but low-level edits can produce one; remove such edges too so v really ends isolated.
    while (halfedge(v).is_valid())
        remove_boundary_edge(edge(halfedge(v)));
    delete_vertex_flag(v);
}

bool SurfaceMesh::is_split_ok(Face f, Vertex a, Vertex b) const
{
    if (!is_valid(f) || !is_valid(a) || !is_valid(b) || a == b)
        return false;
    Halfedge ha, hb;
    const Halfedge start = halfedge(f);
    Halfedge h = start;
    do
    {
        if (to_vertex(h) == a)
            ha = h;
        if (to_vertex(h) == b)
            hb = h;
        h = next(h);
    } while (h != start);
    if (!ha.is_valid() || !hb.is_valid())
        return false;
    if (to_vertex(next(ha)) == b || to_vertex(next(hb)) == a)
        return false;
    return !find_halfedge(a, b).is_valid();
}

Halfedge SurfaceMesh::split_face(Face f, Vertex a, Vertex b)
{
    if (!is_split_ok(f, a, b))
        throw TopologyError("split_face: the diagonal is not allowed in this face");
    if (observer_)
        observer_->face_removing(f);
    Halfedge ha_in, hb_in;
    const Halfedge start = halfedge(f);
    Halfedge h = start;
    do
    {
        if (to_vertex(h) == a)
            ha_in = h;
        if (to_vertex(h) == b)
            hb_in = h;
        h = next(h);
    } while (h != start);
    const Halfedge a_out = next(ha_in);
    const Halfedge b_out = next(hb_in);
    const Halfedge x = new_edge(a, b);
    const Halfedge y = opposite(x);
    const Face g = new_face();
    set_next(ha_in, x);
    set_next(x, b_out);
    set_next(hb_in, y);
    set_next(y, a_out);
    // x and the corners from b round to a form the new face; y and the rest keep f.
    h = x;
    do
    {
        links_[h].face = g;
        h = next(h);
    } while (h != x);
    links_[y].face = f;
    fhalf_[f] = y;
    fhalf_[g] = x;
    if (observer_)
    {
        observer_->face_added(f);
        observer_->face_added(g);
    }
    return x;
}

bool SurfaceMesh::is_remove_edge_ok(Edge e) const
{
    if (!is_valid(e))
        return false;
    const Halfedge h = halfedge(e, 0);
    const Halfedge o = halfedge(e, 1);
    const Face fh = face(h), fo = face(o);
    if (!fh.is_valid() || !fo.is_valid() || fh == fo)
        return false;
    return valence(to_vertex(h)) >= 3 && valence(to_vertex(o)) >= 3;
}

Face SurfaceMesh::remove_edge(Edge e)
{
    if (!is_remove_edge_ok(e))
        throw TopologyError("remove_edge: the edge does not separate two faces that can merge");
    // Keep the older (lower-index) face, so that split_face followed by remove_edge gives the
    // original face its handle back.
    const int keep = face(halfedge(e, 0)).idx() < face(halfedge(e, 1)).idx() ? 0 : 1;
    const Halfedge h = halfedge(e, keep);
    const Halfedge o = halfedge(e, 1 - keep);
    const Face fh = face(h), fo = face(o);
    if (observer_)
    {
        observer_->face_removing(fh);
        observer_->face_removing(fo);
        observer_->edge_removing(e);
    }
    const Halfedge a = prev(h), b = next(h), c = prev(o), d = next(o);
    for (Halfedge x = d; x != o; x = next(x))
        links_[x].face = fh;
    set_next(a, d);
    set_next(c, b);
    const Vertex vh = to_vertex(h), vo = to_vertex(o);
    if (vout_[vh] == o)
        vout_[vh] = b;
    if (vout_[vo] == h)
        vout_[vo] = d;
    fhalf_[fh] = a;
    free_face_slot(fo);
    free_edge_slot(e);
    if (observer_)
        observer_->face_added(fh);
    return fh;
}

void SurfaceMesh::build_faces(const std::vector<std::vector<MeshIndex>>& faces)
{
    if (edges_size() != 0 || faces_size() != 0)
        throw TopologyError("build_faces: the mesh already has edges or faces");
    const size_t nv = vertices_size();
    size_t n_corners = 0;
    for (const auto& poly : faces)
        n_corners += poly.size();
    std::unordered_map<uint64_t, MeshIndex> directed;
    directed.reserve(n_corners);
    eprops_.reserve(n_corners / 2 + 1);
    hprops_.reserve(n_corners + 2);
    fprops_.reserve(faces.size());

    for (size_t fi = 0; fi < faces.size(); ++fi)
    {
        const auto& poly = faces[fi];
        const std::string where = "face " + std::to_string(fi);
        if (poly.size() < 3)
            throw TopologyError(where + " has fewer than three vertices");
        for (size_t i = 0; i < poly.size(); ++i)
        {
            if (poly[i] >= nv)
                throw TopologyError(where + " uses vertex " + std::to_string(poly[i]) + ", out of range");
            for (size_t j = 0; j < i; ++j)
                if (poly[j] == poly[i])
                    throw TopologyError(where + " visits vertex " + std::to_string(poly[i]) + " twice");
        }
        const Face f = new_face();
        const size_t n = poly.size();
        HalfedgeBuffer hs;
        for (size_t i = 0; i < n; ++i)
        {
            const MeshIndex a = poly[i], b = poly[(i + 1) % n];
            if (directed.count(directed_key(a, b)))
                throw TopologyError("edge " + std::to_string(a) + "-" + std::to_string(b) + " of " + where +
                                    " is used twice in the same direction: the faces are not "
                                    "consistently oriented, or the edge has more than two faces");
            Halfedge h;
            const auto twin = directed.find(directed_key(b, a));
            if (twin != directed.end())
                h = opposite(Halfedge(twin->second));
            else
                h = new_edge(Vertex(a), Vertex(b));
            directed.emplace(directed_key(a, b), h.idx());
            links_[h].face = f;
            hs.push_back(h);
        }
        for (size_t i = 0; i < n; ++i)
            set_next(hs[i], hs[(i + 1) % n]);
        fhalf_[f] = hs[0];
    }

    // Each vertex keeps a boundary outgoing halfedge if it has one; a second one means two
    // separate gaps (two fans meeting at a point), which a manifold cannot have.
    std::vector<MeshIndex> degree(nv, 0);
    for (MeshIndex hi = 0; hi < halfedges_size(); ++hi)
    {
        const Halfedge h(hi);
        const Vertex from = from_vertex(h);
        ++degree[from.idx()];
        if (!vout_[from].is_valid() || (is_boundary(h) && !is_boundary(vout_[from])))
            vout_[from] = h;
        else if (is_boundary(h) && is_boundary(vout_[from]))
            throw TopologyError("vertex " + std::to_string(from.idx()) +
                                " is non-manifold: it lies on two separate boundary gaps");
    }
    for (MeshIndex hi = 0; hi < halfedges_size(); ++hi)
    {
        const Halfedge h(hi);
        if (is_boundary(h))
            set_next(h, vout_[to_vertex(h)]);
    }
    for (MeshIndex vi = 0; vi < nv; ++vi)
    {
        const Vertex v(vi);
        if (degree[vi] != 0 && valence(v) != degree[vi])
            throw TopologyError("vertex " + std::to_string(vi) + " is non-manifold: its faces form more than one fan");
    }
}

void SurfaceMesh::reserve(size_t n_vertices, size_t n_edges, size_t n_faces)
{
    vprops_.reserve(n_vertices);
    eprops_.reserve(n_edges);
    hprops_.reserve(2 * n_edges);
    fprops_.reserve(n_faces);
    on_reserve(n_vertices);
}

bool SurfaceMesh::has_capacity_for(size_t more_vertices, size_t more_edges, size_t more_faces) const
{
    // The built-in arrays are representative: every array of a container is reserved together.
    return vertices_size() + more_vertices <= vout_.vector().capacity() &&
           edges_size() + more_edges <= edeleted_.vector().capacity() &&
           halfedges_size() + 2 * more_edges <= links_.vector().capacity() &&
           faces_size() + more_faces <= fhalf_.vector().capacity() && has_extra_capacity_for(more_vertices);
}

void SurfaceMesh::garbage_collection(GarbageMap* map)
{
    GarbageMap local;
    GarbageMap& m = map ? *map : local;
    std::vector<MeshIndex> vkept, ekept, hkept, fkept;
    m.vertices.assign(vertices_size(), kInvalidMeshIndex);
    m.edges.assign(edges_size(), kInvalidMeshIndex);
    m.halfedges.assign(halfedges_size(), kInvalidMeshIndex);
    m.faces.assign(faces_size(), kInvalidMeshIndex);
    for (MeshIndex i = 0; i < vertices_size(); ++i)
        if (!vdeleted_.vector()[i])
        {
            m.vertices[i] = static_cast<MeshIndex>(vkept.size());
            vkept.push_back(i);
        }
    for (MeshIndex i = 0; i < edges_size(); ++i)
        if (!edeleted_.vector()[i])
        {
            m.edges[i] = static_cast<MeshIndex>(ekept.size());
            m.halfedges[2 * i] = static_cast<MeshIndex>(hkept.size());
            hkept.push_back(2 * i);
            m.halfedges[2 * i + 1] = static_cast<MeshIndex>(hkept.size());
            hkept.push_back(2 * i + 1);
            ekept.push_back(i);
        }
    for (MeshIndex i = 0; i < faces_size(); ++i)
        if (!fdeleted_.vector()[i])
        {
            m.faces[i] = static_cast<MeshIndex>(fkept.size());
            fkept.push_back(i);
        }
    vprops_.compact(vkept);
    eprops_.compact(ekept);
    hprops_.compact(hkept);
    fprops_.compact(fkept);

    const auto remap_h = [&m](Halfedge h) { return h.is_valid() ? Halfedge(m.halfedges[h.idx()]) : h; };
    for (Halfedge& h : vout_.vector())
        h = remap_h(h);
    for (HalfedgeLinks& l : links_.vector())
    {
        l.to = Vertex(m.vertices[l.to.idx()]);
        l.next = remap_h(l.next);
        l.prev = remap_h(l.prev);
        if (l.face.is_valid())
            l.face = Face(m.faces[l.face.idx()]);
    }
    for (Halfedge& h : fhalf_.vector())
        h = remap_h(h);
    deleted_vertices_ = deleted_edges_ = deleted_faces_ = 0;
    free_edges_.clear();
    free_faces_.clear();
    on_compacted();
    if (observer_)
        observer_->compacted(m);
}

void SurfaceMesh::clear()
{
    vprops_.resize(0);
    hprops_.resize(0);
    eprops_.resize(0);
    fprops_.resize(0);
    deleted_vertices_ = deleted_edges_ = deleted_faces_ = 0;
    free_edges_.clear();
    free_faces_.clear();
    on_compacted();
}

} // namespace zomeify
