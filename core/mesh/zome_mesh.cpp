#include "core/mesh/zome_mesh.h"

#include <sstream>

#include "core/mesh/topology_error.h"

namespace zomeify {

namespace {

std::string describe(const ZVec& p)
{
    std::ostringstream os;
    os << p;
    return os.str();
}

} // namespace

ZomeMesh::ZomeMesh()
{
    zpos_ = add_vertex_property<ZVec>("v:zpos");
    zvec_ = add_halfedge_property<uint8_t>("h:zvector", kNoZomeVector);
}

ZomeMesh::ZomeMesh(const ZomeMesh& other) : SurfaceMesh(other), index_(other.index_) { bind_properties(); }

ZomeMesh& ZomeMesh::operator=(const ZomeMesh& other)
{
    if (this == &other)
        return *this;
    SurfaceMesh::operator=(other);
    index_ = other.index_;
    bind_properties();
    return *this;
}

void ZomeMesh::bind_properties()
{
    zpos_ = get_vertex_property<ZVec>("v:zpos");
    zvec_ = get_halfedge_property<uint8_t>("h:zvector");
}

Vertex ZomeMesh::add_vertex(ZVec p)
{
    if (!is_position_free(p))
        throw TopologyError("add_vertex: a node already sits at " + describe(p));
    const Vertex v = new_vertex();
    zpos_[v] = p;
    index_.insert(p, v);
    notify_vertex_added(v);
    return v;
}

Vertex ZomeMesh::add_vertex_unchecked(ZVec p)
{
    const Vertex v = new_vertex();
    zpos_[v] = p;
    index_.insert(p, v);
    notify_vertex_added(v);
    return v;
}

void ZomeMesh::move_vertex(Vertex v, ZVec p)
{
    if (zpos_[v] == p)
        return;
    if (!is_position_free(p))
        throw TopologyError("move_vertex: a node already sits at " + describe(p));
    if (observer())
        observer()->vertex_moving(v);
    if (index_.find(zpos_[v]) == v)
        index_.erase(zpos_[v]);
    zpos_[v] = p;
    index_.insert(p, v);
    const Halfedge start = halfedge(v);
    if (start.is_valid())
    {
        Halfedge h = start;
        do
        {
            update_vector_id(h);
            update_vector_id(opposite(h));
            h = ccw_rotated(h);
        } while (h != start);
    }
    if (observer())
        observer()->vertex_moved(v);
}

Halfedge ZomeMesh::find_slot(Vertex v, int s) const
{
    const Halfedge start = halfedge(v);
    if (!start.is_valid())
        return {};
    Halfedge h = start;
    do
    {
        if (slot(h) == s)
            return h;
        h = ccw_rotated(h);
    } while (h != start);
    return {};
}

bool ZomeMesh::is_new_strut_ok(Vertex a, Vertex b) const
{
    if (a == b)
        return false;
    const int s = slot_of(zpos_[b] - zpos_[a]);
    // A second a–b edge would have the same vector, so the free-slot test also rules it out.
    return s >= 0 && is_slot_free(a, s) && is_slot_free(b, opposite_slot(s));
}

int ZomeMesh::new_strut_id(const ZVec& p, Vertex b) const
{
    const int id = vector_id_of(zpos_[b] - p);
    if (id < 0 || !is_slot_free(b, opposite_slot(vector_slot(id))))
        return -1;
    return id;
}

void ZomeMesh::update_vector_id(Halfedge h)
{
    const int id = vector_id_of(vector(h));
    zvec_[h] = id < 0 ? kNoZomeVector : static_cast<uint8_t>(id);
}

void ZomeMesh::on_edge_added(Edge e)
{
    // One table lookup per edge; the opposite side follows from the slot pairing (s ^ 1).
    const Halfedge h = halfedge(e, 0);
    update_vector_id(h);
    const uint8_t id = zvec_[h];
    zvec_[opposite(h)] =
        id == kNoZomeVector ? kNoZomeVector
                            : static_cast<uint8_t>(zomeify::vector_id(opposite_slot(vector_slot(id)), vector_size(id)));
}

void ZomeMesh::on_vertex_removing(Vertex v)
{
    if (index_.find(zpos_[v]) == v)
        index_.erase(zpos_[v]);
}

void ZomeMesh::on_compacted() { rebuild_index(); }

void ZomeMesh::rebuild_index()
{
    index_.clear();
    index_.reserve(n_vertices());
    for (MeshIndex i = 0; i < vertices_size(); ++i)
    {
        const Vertex v(i);
        if (!is_deleted(v))
            index_.insert(zpos_[v], v);
    }
}

} // namespace zomeify
