#pragma once
//! \file zome_mesh.h
//! ZomeMesh: the halfedge mesh of a Zome model (design.md §3). A SurfaceMesh plus
//!  - "v:zpos" (ZVec): the exact position of every node;
//!  - "h:zvector" (uint8_t): the Zome vector id (0..185, slot·3 + size) of the strut vector
//!    from → to of every halfedge, computed when the edge is created (kNoZomeVector if the vector
//!    is not a Zome vector, which validate() reports);
//!  - a global exact position → node index, kept in sync by every primitive, so that "no two
//!    nodes at one position" is an O(1) check.
//!
//! Reads are safe from any number of threads. Edits are not: the annealer serialises commits
//! and keeps capacity reserved (reserve(), has_capacity_for()) so that neither the arrays nor the
//! position index move under concurrent readers.

#include <cstdint>

#include "core/mesh/position_index.h"
#include "core/mesh/surface_mesh.h"
#include "core/zome/slots.h"
#include "core/zome/zvec.h"

namespace zomeify {

//! The stored vector id of a halfedge whose vector is not a Zome vector.
inline constexpr uint8_t kNoZomeVector = 0xFF;

class ZomeMesh : public SurfaceMesh
{
public:
    ZomeMesh();
    ZomeMesh(const ZomeMesh& other);
    ZomeMesh& operator=(const ZomeMesh& other);
    ZomeMesh(ZomeMesh&& other) noexcept = default;
    ZomeMesh& operator=(ZomeMesh&& other) noexcept = default;
    ~ZomeMesh() override = default;

    //! \name Positions
    //!@{
    //! Adds an isolated node at p; throws TopologyError if a node already sits at p. (p is taken
    //! by value: it may be another node's position, and appending can move the position array.)
    Vertex add_vertex(ZVec p);
    //! The node at p, or invalid (exact lookup, O(1)).
    Vertex find_vertex(const ZVec& p) const { return index_.find(p); }
    bool is_position_free(const ZVec& p) const { return !index_.contains(p); }
    const ZVec& position(Vertex v) const { return zpos_[v]; }
    //! The property holding all positions (indexed by vertex; deleted entries are stale).
    const VertexProperty<ZVec>& positions() const { return zpos_; }
    //! Moves v to the free position p, keeping the index in sync, and recomputes the vector ids
    //! of v's edges. Throws TopologyError if p is occupied by another node.
    void move_vertex(Vertex v, ZVec p);
    //! Number of entries in the position index (equals n_vertices() when consistent).
    size_t position_index_size() const { return index_.size(); }
    //! The position index itself (for validation and statistics).
    const PositionIndex& position_index() const { return index_; }
    //!@}

    //! \name Struts
    //!@{
    //! The strut vector from → to of h (exact).
    ZVec vector(Halfedge h) const { return zpos_[to_vertex(h)] - zpos_[from_vertex(h)]; }
    //! The stored Zome vector id (0..185) of h, or kNoZomeVector.
    uint8_t vector_id(Halfedge h) const { return zvec_[h]; }
    //! The slot (0..61) of h at its from-vertex, or -1 if h is not a Zome vector.
    int slot(Halfedge h) const
    {
        const uint8_t id = zvec_[h];
        return id == kNoZomeVector ? -1 : vector_slot(id);
    }
    //! The strut kind of e (valid only if the edge is a Zome vector).
    StrutKind kind(Edge e) const { return vector_kind(zvec_[halfedge(e, 0)]); }
    //! The outgoing halfedge of v in that slot, or invalid (O(valence)).
    Halfedge find_slot(Vertex v, int slot) const;
    //! Whether the vector from a to b is a Zome vector (exact; O(1)).
    bool is_zome_pair(Vertex a, Vertex b) const { return vector_id_of(zpos_[b] - zpos_[a]) >= 0; }
    //! Whether v has no strut in that slot (O(valence)).
    bool is_slot_free(Vertex v, int slot) const { return !find_slot(v, slot).is_valid(); }
    //! Whether a new strut a–b is allowed (design.md §3.4): a Zome vector, its slot free at a and
    //! the opposite slot free at b, and a, b not joined already (no doubly connected pair).
    bool is_new_strut_ok(Vertex a, Vertex b) const;
    //! The same for a strut from a node still to be placed at p to node b: the vector id of
    //! p → b if it is a Zome vector whose slot is free at b, otherwise -1.
    int new_strut_id(const ZVec& p, Vertex b) const;
    //!@}

    //! \name Low-level setters (break invariants; for validator tests and repair code)
    //!@{
    //! Sets a position without touching the index.
    void set_position_unchecked(Vertex v, ZVec p) { zpos_[v] = p; }
    //! Overwrites the stored vector id of one halfedge.
    void set_vector_id_unchecked(Halfedge h, uint8_t id) { zvec_[h] = id; }
    //! Adds a node at p even if p is occupied (the index keeps the older node).
    Vertex add_vertex_unchecked(ZVec p);
    //!@}

protected:
    void on_edge_added(Edge e) override;
    void on_vertex_removing(Vertex v) override;
    void on_compacted() override;
    void on_reserve(size_t n_vertices) override { index_.reserve(n_vertices); }
    bool has_extra_capacity_for(size_t more_vertices) const override { return index_.has_capacity_for(more_vertices); }

private:
    void bind_properties();
    void rebuild_index();
    void update_vector_id(Halfedge h);

    VertexProperty<ZVec> zpos_;
    HalfedgeProperty<uint8_t> zvec_;
    PositionIndex index_;
};

} // namespace zomeify
