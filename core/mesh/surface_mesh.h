#pragma once
//! \file surface_mesh.h
//! SurfaceMesh: halfedge connectivity of a polygon mesh in flat arrays (pmp's layout; style.md §7
//! rules 2–3). Halfedges 2e and 2e+1 are the two sides of edge e, so opposite(h) = h ^ 1. Each
//! halfedge stores its to-vertex, next, prev and face; a vertex stores one outgoing halfedge (a
//! boundary one when the vertex is on a boundary); a face stores one of its halfedges. Faces are
//! counter-clockwise seen from outside. A boundary halfedge has no face; boundary halfedges are
//! linked by next/prev into the hole's cycle, so all outgoing halfedges of a vertex form one
//! rotation cycle even while an edit has the surface open.
//!
//! Deletion is lazy: elements are flagged and skipped by the ranges and circulators, and
//! garbage_collection() compacts the arrays (only in a synchronized state: it moves everything).
//! New elements are appended; if other threads read the mesh while one thread appends, call
//! reserve() first so the arrays never reallocate during that phase.
//!
//! Queries are inline and O(1) (find_halfedge and valence are O(valence)); no query allocates.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/handles.h"
#include "core/mesh/mesh_observer.h"
#include "core/mesh/properties.h"

namespace zomeify {

//! The four pointers of one halfedge (one array of these, for locality in the annealer's loops).
struct HalfedgeLinks
{
    Vertex to;     //!< the vertex the halfedge points to
    Halfedge next; //!< next halfedge in its face (or boundary cycle)
    Halfedge prev; //!< previous halfedge in its face (or boundary cycle)
    Face face;     //!< the face on its left, invalid for a boundary halfedge
};

//! Why add_face refused a polygon (nothing is changed when it does).
enum class AddFaceStatus : uint8_t
{
    Ok,
    TooFewVertices, //!< fewer than three vertices
    InvalidVertex,  //!< a handle out of range or deleted
    RepeatedVertex, //!< a vertex occurs twice in the polygon
    ComplexVertex,  //!< a vertex is already surrounded by faces (would become non-manifold)
    ComplexEdge,    //!< an edge already has a face on this side (non-manifold or flipped face)
    RelinkFailed    //!< the fans around a vertex cannot be ordered into one disc
};

//! A short human-readable reason for a status.
const char* to_string(AddFaceStatus status);

//! Old index → new index maps produced by garbage_collection() (kInvalidMeshIndex for removed).
struct GarbageMap
{
    std::vector<MeshIndex> vertices;
    std::vector<MeshIndex> halfedges;
    std::vector<MeshIndex> edges;
    std::vector<MeshIndex> faces;
};

class SurfaceMesh
{
public:
    SurfaceMesh();
    virtual ~SurfaceMesh() = default;
    SurfaceMesh(const SurfaceMesh& other);
    SurfaceMesh& operator=(const SurfaceMesh& other);
    SurfaceMesh(SurfaceMesh&& other) noexcept;
    SurfaceMesh& operator=(SurfaceMesh&& other) noexcept;

    //! \name Sizes
    //! `*_size()` counts array entries (deleted included), `n_*()` live elements.
    //!@{
    size_t vertices_size() const { return vprops_.size(); }
    size_t halfedges_size() const { return 2 * eprops_.size(); }
    size_t edges_size() const { return eprops_.size(); }
    size_t faces_size() const { return fprops_.size(); }
    size_t n_vertices() const { return vertices_size() - deleted_vertices_; }
    size_t n_edges() const { return edges_size() - deleted_edges_; }
    size_t n_halfedges() const { return 2 * n_edges(); }
    size_t n_faces() const { return faces_size() - deleted_faces_; }
    bool is_empty() const { return n_vertices() == 0; }
    //! Whether some element is flagged deleted (garbage_collection() would change indices).
    bool has_garbage() const { return deleted_vertices_ + deleted_edges_ + deleted_faces_ > 0; }
    //!@}

    //! \name Element status
    //!@{
    bool is_deleted(Vertex v) const { return vdeleted_[v] != 0; }
    bool is_deleted(Halfedge h) const { return edeleted_[edge(h)] != 0; }
    bool is_deleted(Edge e) const { return edeleted_[e] != 0; }
    bool is_deleted(Face f) const { return fdeleted_[f] != 0; }
    //! In range and not deleted.
    bool is_valid(Vertex v) const { return v.idx() < vertices_size() && !is_deleted(v); }
    bool is_valid(Halfedge h) const { return h.idx() < halfedges_size() && !is_deleted(h); }
    bool is_valid(Edge e) const { return e.idx() < edges_size() && !is_deleted(e); }
    bool is_valid(Face f) const { return f.idx() < faces_size() && !is_deleted(f); }
    //!@}

    //! \name Connectivity queries (O(1))
    //!@{
    //! One outgoing halfedge of v (a boundary one if v is on a boundary); invalid if isolated.
    Halfedge halfedge(Vertex v) const { return vout_[v]; }
    //! One halfedge of f.
    Halfedge halfedge(Face f) const { return fhalf_[f]; }
    //! Side i (0 or 1) of edge e.
    static Halfedge halfedge(Edge e, int i) { return Halfedge((e.idx() << 1) + static_cast<MeshIndex>(i)); }
    static Edge edge(Halfedge h) { return Edge(h.idx() >> 1); }
    static Halfedge opposite(Halfedge h) { return Halfedge(h.idx() ^ 1U); }
    Vertex to_vertex(Halfedge h) const { return links_[h].to; }
    Vertex from_vertex(Halfedge h) const { return links_[opposite(h)].to; }
    Halfedge next(Halfedge h) const { return links_[h].next; }
    Halfedge prev(Halfedge h) const { return links_[h].prev; }
    Face face(Halfedge h) const { return links_[h].face; }
    const HalfedgeLinks& links(Halfedge h) const { return links_[h]; }
    //! Endpoint i (0 = from, 1 = to of side 0) of edge e.
    Vertex vertex(Edge e, int i) const { return to_vertex(halfedge(e, 1 - i)); }
    //! The next outgoing halfedge counter-clockwise around from_vertex(h), seen from outside.
    Halfedge ccw_rotated(Halfedge h) const { return opposite(prev(h)); }
    //! The next outgoing halfedge clockwise around from_vertex(h), seen from outside.
    Halfedge cw_rotated(Halfedge h) const { return next(opposite(h)); }

    bool is_boundary(Halfedge h) const { return !face(h).is_valid(); }
    bool is_boundary(Edge e) const { return is_boundary(halfedge(e, 0)) || is_boundary(halfedge(e, 1)); }
    //! Whether v is on a boundary (isolated vertices count as boundary).
    bool is_boundary(Vertex v) const
    {
        const Halfedge h = halfedge(v);
        return !h.is_valid() || is_boundary(h);
    }
    //! Whether the face has an edge on a boundary.
    bool is_boundary(Face f) const;
    bool is_isolated(Vertex v) const { return !halfedge(v).is_valid(); }
    //!@}

    //! \name Local queries (O(valence), no allocation)
    //!@{
    //! The halfedge from `from` to `to`, or invalid.
    Halfedge find_halfedge(Vertex from, Vertex to) const;
    //! The edge between a and b, or invalid.
    Edge find_edge(Vertex a, Vertex b) const;
    //! Number of edges at v.
    size_t valence(Vertex v) const;
    //! Number of corners of f.
    size_t valence(Face f) const;
    //!@}

    //! \name Building and local edits
    //! The primitives the annealer's operators are made of (paper §5.1): add/remove vertex and
    //! add/remove face, plus the two O(1) diagonal edits. Each comes with a check that has no
    //! side effects; the act functions throw TopologyError when the check fails.
    //!@{
    //! Appends an isolated vertex.
    Vertex add_vertex();
    //! Checks whether add_face(vertices) would succeed, without changing anything.
    AddFaceStatus check_add_face(std::span<const Vertex> vertices) const;
    //! Adds a polygon (counter-clockwise seen from outside) and links it to its neighbours;
    //! missing edges are created. Throws TopologyError if check_add_face fails.
    Face add_face(std::span<const Vertex> vertices);
    //! add_face that returns an invalid face (and changes nothing) instead of throwing.
    Face try_add_face(std::span<const Vertex> vertices);
    Face add_triangle(Vertex a, Vertex b, Vertex c);
    Face add_quad(Vertex a, Vertex b, Vertex c, Vertex d);
    //! Removes a face, leaving a hole. Edges with no face left are removed; vertices stay, even
    //! when they become isolated (remove them with remove_vertex).
    void remove_face(Face f);
    //! Removes every face and edge around v, then v itself. The faces' outer edges (v's link)
    //! remain as the boundary of a hole.
    void remove_vertex(Vertex v);
    //! Whether split_face(f, a, b) may insert the diagonal a–b: both are corners of f, not
    //! adjacent in f, and not already joined by an edge.
    bool is_split_ok(Face f, Vertex a, Vertex b) const;
    //! Splits f by a new edge from a to b; returns the new halfedge a→b (its face is the part
    //! that follows a→b, the other part keeps f). Throws TopologyError if !is_split_ok.
    Halfedge split_face(Face f, Vertex a, Vertex b);
    //! Whether remove_edge(e) may merge the two faces of e: e has two distinct faces and both
    //! endpoints keep valence ≥ 2 (the merged face then has no dangling edge).
    bool is_remove_edge_ok(Edge e) const;
    //! Removes e and merges its two faces into one; the lower-index face is kept and returned
    //! (so split_face then remove_edge restores the original handle). Throws TopologyError if
    //! !is_remove_edge_ok.
    Face remove_edge(Edge e);
    //! Builds faces over the existing vertices 0..n-1 in one pass (the mesh must have no edges).
    //! Throws TopologyError naming the face or vertex at fault for a repeated vertex, an edge
    //! used twice in one direction, an edge with more than two faces or a vertex whose faces do
    //! not form one fan.
    void build_faces(const std::vector<std::vector<MeshIndex>>& faces);
    //! Reserves array capacity (so appends up to these sizes never reallocate).
    void reserve(size_t n_vertices, size_t n_edges, size_t n_faces);
    //! Whether appending the given numbers of elements would fit the current capacity.
    bool has_capacity_for(size_t more_vertices, size_t more_edges, size_t more_faces) const;
    //! Removes deleted elements and compacts every array (live elements keep their order).
    void garbage_collection(GarbageMap* map = nullptr);
    //! Removes every element; the properties stay (empty).
    void clear();
    //!@}

    //! \name Properties
    //! Typed named per-element arrays; the built-in ones are "v:connectivity", "h:links",
    //! "f:connectivity" and the deletion flags "v:deleted", "e:deleted", "f:deleted".
    //!@{
    template <class T>
    VertexProperty<T> add_vertex_property(const std::string& name, T value = T())
    {
        return VertexProperty<T>(vprops_.add<T>(name, std::move(value)));
    }
    template <class T>
    HalfedgeProperty<T> add_halfedge_property(const std::string& name, T value = T())
    {
        return HalfedgeProperty<T>(hprops_.add<T>(name, std::move(value)));
    }
    template <class T>
    EdgeProperty<T> add_edge_property(const std::string& name, T value = T())
    {
        return EdgeProperty<T>(eprops_.add<T>(name, std::move(value)));
    }
    template <class T>
    FaceProperty<T> add_face_property(const std::string& name, T value = T())
    {
        return FaceProperty<T>(fprops_.add<T>(name, std::move(value)));
    }
    //! The property of that name and type; invalid (is_valid() false) if there is none.
    template <class T>
    VertexProperty<T> get_vertex_property(const std::string& name) const
    {
        return VertexProperty<T>(vprops_.get<T>(name));
    }
    template <class T>
    HalfedgeProperty<T> get_halfedge_property(const std::string& name) const
    {
        return HalfedgeProperty<T>(hprops_.get<T>(name));
    }
    template <class T>
    EdgeProperty<T> get_edge_property(const std::string& name) const
    {
        return EdgeProperty<T>(eprops_.get<T>(name));
    }
    template <class T>
    FaceProperty<T> get_face_property(const std::string& name) const
    {
        return FaceProperty<T>(fprops_.get<T>(name));
    }
    template <class T>
    void remove_property(VertexProperty<T>& p)
    {
        remove_array(vprops_, p);
    }
    template <class T>
    void remove_property(HalfedgeProperty<T>& p)
    {
        remove_array(hprops_, p);
    }
    template <class T>
    void remove_property(EdgeProperty<T>& p)
    {
        remove_array(eprops_, p);
    }
    template <class T>
    void remove_property(FaceProperty<T>& p)
    {
        remove_array(fprops_, p);
    }
    std::vector<std::string> vertex_property_names() const { return vprops_.names(); }
    std::vector<std::string> halfedge_property_names() const { return hprops_.names(); }
    std::vector<std::string> edge_property_names() const { return eprops_.names(); }
    std::vector<std::string> face_property_names() const { return fprops_.names(); }
    //!@}

    //! \name Observer
    //! One optional observer of the primitive edits (mesh_observer.h); nullptr detaches.
    //!@{
    void set_observer(MeshObserver* observer) { observer_ = observer; }
    MeshObserver* observer() const { return observer_; }
    //!@}

    //! \name Low-level setters
    //! These break invariants on purpose; they exist for tests of the validator and for code
    //! that rebuilds connectivity wholesale. set_next also sets prev of the target.
    //!@{
    void set_next(Halfedge h, Halfedge n)
    {
        links_[h].next = n;
        links_[n].prev = h;
    }
    void set_vertex(Halfedge h, Vertex v) { links_[h].to = v; }
    void set_face(Halfedge h, Face f) { links_[h].face = f; }
    void set_halfedge(Vertex v, Halfedge h) { vout_[v] = h; }
    void set_halfedge(Face f, Halfedge h) { fhalf_[f] = h; }
    //!@}

    //! On: an edge or face slot deleted since the last garbage_collection() is filled again by the
    //! next new edge or face, instead of appending (deleted vertex slots are never refilled). For
    //! the annealer: a commit's new faces then take the slots of the faces it removed, so the
    //! elements of one region stay where they were instead of being appended, side by side with
    //! another thread's. Off by default: indices of new elements are then always the highest.
    void set_slot_reuse(bool on);

protected:
    //! Called after a new edge (both halfedges linked to their vertices) is appended.
    virtual void on_edge_added(Edge) {}
    //! Called just before v is flagged deleted.
    virtual void on_vertex_removing(Vertex) {}
    //! Called at the end of garbage_collection() and clear().
    virtual void on_compacted() {}
    //! Called at the end of reserve(), for derived structures sized by the vertex count.
    virtual void on_reserve(size_t) {}
    //! Extra condition of has_capacity_for() from derived structures.
    virtual bool has_extra_capacity_for(size_t) const { return true; }

    //! Appends an isolated vertex without notifying the observer (derived classes complete the
    //! vertex, then call notify_vertex_added).
    Vertex new_vertex();
    void notify_vertex_added(Vertex v)
    {
        if (observer_)
            observer_->vertex_added(v);
    }
    //! Appends an edge from a to b (no faces, next/prev unset).
    Halfedge new_edge(Vertex a, Vertex b);
    //! Appends a face with no halfedge (the caller links it).
    Face new_face();

private:
    template <class P>
    static void remove_array(PropertyContainer& c, P& p)
    {
        c.remove(p.array());
        p = P();
    }
    void bind_builtin_properties();
    void add_builtin_properties();
    void free_edge_slot(Edge e);
    void free_face_slot(Face f);
    // Points v's outgoing halfedge at a boundary one if v has any (the invariant is_boundary uses).
    void adjust_outgoing_halfedge(Vertex v);
    // Unlinks one edge whose two sides are both boundary and flags it deleted.
    void remove_boundary_edge(Edge e);
    void delete_vertex_flag(Vertex v);

    PropertyContainer vprops_, hprops_, eprops_, fprops_;
    VertexProperty<Halfedge> vout_;
    HalfedgeProperty<HalfedgeLinks> links_;
    FaceProperty<Halfedge> fhalf_;
    VertexProperty<uint8_t> vdeleted_;
    EdgeProperty<uint8_t> edeleted_;
    FaceProperty<uint8_t> fdeleted_;
    size_t deleted_vertices_ = 0, deleted_edges_ = 0, deleted_faces_ = 0;
    bool slot_reuse_ = false;
    std::vector<MeshIndex> free_edges_, free_faces_; // deleted slots to refill (slot_reuse_)
    MeshObserver* observer_ = nullptr;
};

} // namespace zomeify
