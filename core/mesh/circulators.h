#pragma once
//! \file circulators.h
//! Ranges around one vertex or one face, for range-for loops in the annealer's inner loop. They
//! hold three words, never allocate, and walk the links directly:
//!   for (Halfedge h : outgoing_halfedges(mesh, v))   // counter-clockwise seen from outside
//!   for (Vertex w : adjacent_vertices(mesh, v))
//!   for (Face f : incident_faces(mesh, v))            // boundary gaps skipped
//!   for (Halfedge h : face_halfedges(mesh, f))        // in face order
//!   for (Vertex w : face_vertices(mesh, f))           // to-vertices, in face order
//! An isolated vertex gives empty ranges. Edits during a walk invalidate it.

#include <cstddef>
#include <iterator>

#include "core/mesh/surface_mesh.h"

namespace zomeify {

namespace detail {

//! Step and value policies of the five circulators.
struct AroundVertex
{
    static Halfedge step(const SurfaceMesh& m, Halfedge h) { return m.ccw_rotated(h); }
};
struct AroundFace
{
    static Halfedge step(const SurfaceMesh& m, Halfedge h) { return m.next(h); }
};
struct AsHalfedge
{
    using value_type = Halfedge;
    static bool skip(const SurfaceMesh&, Halfedge) { return false; }
    static Halfedge get(const SurfaceMesh&, Halfedge h) { return h; }
};
struct AsToVertex
{
    using value_type = Vertex;
    static bool skip(const SurfaceMesh&, Halfedge) { return false; }
    static Vertex get(const SurfaceMesh& m, Halfedge h) { return m.to_vertex(h); }
};
struct AsFace
{
    using value_type = Face;
    static bool skip(const SurfaceMesh& m, Halfedge h) { return m.is_boundary(h); }
    static Face get(const SurfaceMesh& m, Halfedge h) { return m.face(h); }
};

//! Walks a halfedge cycle once from `start`; `lap` tells the begin (0) from the end (1) when the
//! walk is back at start.
template <class Step, class Value>
class CycleIterator
{
public:
    using value_type = typename Value::value_type;
    using difference_type = std::ptrdiff_t;
    using iterator_category = std::forward_iterator_tag;

    CycleIterator() = default;
    CycleIterator(const SurfaceMesh* m, Halfedge start, bool at_end) : m_(m), start_(start), h_(start), lap_(at_end)
    {
        if (!start.is_valid())
            lap_ = true;
        else if (!lap_)
            skip_filtered();
    }

    value_type operator*() const { return Value::get(*m_, h_); }
    CycleIterator& operator++()
    {
        advance();
        skip_filtered();
        return *this;
    }
    CycleIterator operator++(int)
    {
        CycleIterator tmp = *this;
        ++*this;
        return tmp;
    }
    friend bool operator==(const CycleIterator& a, const CycleIterator& b) { return a.h_ == b.h_ && a.lap_ == b.lap_; }
    //! The halfedge the iterator stands on.
    Halfedge halfedge() const { return h_; }

private:
    void advance()
    {
        h_ = Step::step(*m_, h_);
        if (h_ == start_)
            lap_ = true;
    }
    void skip_filtered()
    {
        while (!lap_ && Value::skip(*m_, h_))
            advance();
    }

    const SurfaceMesh* m_ = nullptr;
    Halfedge start_;
    Halfedge h_;
    bool lap_ = true;
};

template <class Step, class Value>
class CycleRange
{
public:
    using iterator = CycleIterator<Step, Value>;
    CycleRange(const SurfaceMesh& m, Halfedge start) : m_(&m), start_(start) {}
    iterator begin() const { return iterator(m_, start_, false); }
    iterator end() const { return iterator(m_, start_, true); }

private:
    const SurfaceMesh* m_;
    Halfedge start_;
};

} // namespace detail

using OutgoingHalfedgeRange = detail::CycleRange<detail::AroundVertex, detail::AsHalfedge>;
using AdjacentVertexRange = detail::CycleRange<detail::AroundVertex, detail::AsToVertex>;
using IncidentFaceRange = detail::CycleRange<detail::AroundVertex, detail::AsFace>;
using FaceHalfedgeRange = detail::CycleRange<detail::AroundFace, detail::AsHalfedge>;
using FaceVertexRange = detail::CycleRange<detail::AroundFace, detail::AsToVertex>;

//! Outgoing halfedges of v, counter-clockwise seen from outside, from halfedge(v).
inline OutgoingHalfedgeRange outgoing_halfedges(const SurfaceMesh& m, Vertex v) { return {m, m.halfedge(v)}; }
//! The neighbours of v, in the order of outgoing_halfedges.
inline AdjacentVertexRange adjacent_vertices(const SurfaceMesh& m, Vertex v) { return {m, m.halfedge(v)}; }
//! The faces around v (boundary gaps skipped).
inline IncidentFaceRange incident_faces(const SurfaceMesh& m, Vertex v) { return {m, m.halfedge(v)}; }
//! The halfedges of f, from halfedge(f), in face order.
inline FaceHalfedgeRange face_halfedges(const SurfaceMesh& m, Face f) { return {m, m.halfedge(f)}; }
//! The corners of f: to-vertices of face_halfedges (so the first is to_vertex(halfedge(f))).
inline FaceVertexRange face_vertices(const SurfaceMesh& m, Face f) { return {m, m.halfedge(f)}; }
//! The halfedges of the cycle through h (a face, or a hole when h is a boundary halfedge).
inline FaceHalfedgeRange cycle_halfedges(const SurfaceMesh& m, Halfedge h) { return {m, h}; }

} // namespace zomeify
