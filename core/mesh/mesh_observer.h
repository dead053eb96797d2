#pragma once
//! \file mesh_observer.h
//! MeshObserver: callbacks on the primitive edits (style.md §7 rule 4, GC's MutationManager). The
//! annealer's energy keeps global sums over nodes, struts and faces; an observer attached to the
//! mesh updates them as the primitives run, so that commit() leaves them exact.
//!
//! Contract: "removing" callbacks come before the element changes (it is still fully readable),
//! "added" callbacks after it is complete (an edge has its vector id, a face its links). A face
//! whose corners change (split_face, remove_edge) is reported as removing, then added. Edges that
//! disappear with a face are reported. build_faces() and copies report nothing, and a copy does not
//! inherit the observer. Callbacks run on the editing thread, inside the caller's critical section.

#include "core/mesh/handles.h"

namespace zomeify {

struct GarbageMap;

class MeshObserver
{
public:
    virtual ~MeshObserver() = default;
    virtual void vertex_added(Vertex) {}
    virtual void vertex_removing(Vertex) {}
    //! Before and after a node changes position (ZomeMesh::move_vertex); its struts change too.
    virtual void vertex_moving(Vertex) {}
    virtual void vertex_moved(Vertex) {}
    virtual void edge_added(Edge) {}
    virtual void edge_removing(Edge) {}
    virtual void face_added(Face) {}
    virtual void face_removing(Face) {}
    //! After garbage_collection(): every handle held by the observer must be remapped.
    virtual void compacted(const GarbageMap&) {}
};

} // namespace zomeify
