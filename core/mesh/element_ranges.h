#pragma once
//! \file element_ranges.h
//! Ranges over all live elements of a mesh, skipping deleted ones:
//!   for (Vertex v : vertices(mesh)) ...   likewise halfedges, edges, faces.
//! Indices ascend; elements appended during the walk are not visited.

#include <cstddef>
#include <iterator>

#include "core/mesh/surface_mesh.h"

namespace zomeify {

namespace detail {

template <class H>
class ElementIterator
{
public:
    using value_type = H;
    using difference_type = std::ptrdiff_t;
    using iterator_category = std::forward_iterator_tag;

    ElementIterator() = default;
    ElementIterator(const SurfaceMesh* m, MeshIndex i, MeshIndex end) : m_(m), i_(i), end_(end) { skip(); }
    H operator*() const { return H(i_); }
    ElementIterator& operator++()
    {
        ++i_;
        skip();
        return *this;
    }
    ElementIterator operator++(int)
    {
        ElementIterator tmp = *this;
        ++*this;
        return tmp;
    }
    friend bool operator==(const ElementIterator& a, const ElementIterator& b) { return a.i_ == b.i_; }

private:
    void skip()
    {
        while (i_ < end_ && m_->is_deleted(H(i_)))
            ++i_;
    }
    const SurfaceMesh* m_ = nullptr;
    MeshIndex i_ = 0;
    MeshIndex end_ = 0;
};

template <class H>
class ElementRange
{
public:
    ElementRange(const SurfaceMesh& m, size_t size) : m_(&m), end_(static_cast<MeshIndex>(size)) {}
    ElementIterator<H> begin() const { return {m_, 0, end_}; }
    ElementIterator<H> end() const { return {m_, end_, end_}; }

private:
    const SurfaceMesh* m_;
    MeshIndex end_;
};

} // namespace detail

inline detail::ElementRange<Vertex> vertices(const SurfaceMesh& m) { return {m, m.vertices_size()}; }
inline detail::ElementRange<Halfedge> halfedges(const SurfaceMesh& m) { return {m, m.halfedges_size()}; }
inline detail::ElementRange<Edge> edges(const SurfaceMesh& m) { return {m, m.edges_size()}; }
inline detail::ElementRange<Face> faces(const SurfaceMesh& m) { return {m, m.faces_size()}; }

} // namespace zomeify
