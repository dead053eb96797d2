#pragma once
//! \file handles.h
//! Typed index handles of the halfedge mesh: Vertex, Halfedge, Edge and Face (style.md §7 rule 2).
//! A handle is a 32-bit index into the mesh's arrays; the all-ones index means "invalid". Handles of
//! different element kinds do not convert into each other, so a face cannot be passed as a vertex.

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <limits>

namespace zomeify {

//! The index type of every mesh element.
using MeshIndex = uint32_t;
//! The index of an invalid handle.
inline constexpr MeshIndex kInvalidMeshIndex = std::numeric_limits<MeshIndex>::max();

namespace detail {

//! Shared implementation of the four handle types; `Tag` keeps them distinct types.
template <class Tag>
class BaseHandle
{
public:
    //! An invalid handle.
    constexpr BaseHandle() = default;
    //! The handle of element `idx` (kInvalidMeshIndex gives an invalid handle).
    explicit constexpr BaseHandle(MeshIndex idx) : idx_(idx) {}

    //! The element index.
    constexpr MeshIndex idx() const { return idx_; }
    //! False for a default-constructed handle.
    constexpr bool is_valid() const { return idx_ != kInvalidMeshIndex; }
    //! Makes the handle invalid.
    constexpr void reset() { idx_ = kInvalidMeshIndex; }

    friend constexpr bool operator==(BaseHandle, BaseHandle) = default;
    friend constexpr auto operator<=>(BaseHandle, BaseHandle) = default;

private:
    MeshIndex idx_ = kInvalidMeshIndex;
};

struct VertexTag;
struct HalfedgeTag;
struct EdgeTag;
struct FaceTag;

} // namespace detail

//! A node of the mesh.
class Vertex : public detail::BaseHandle<detail::VertexTag>
{
public:
    using BaseHandle::BaseHandle;
};

//! One oriented side of an edge. Halfedges 2e and 2e+1 are the two sides of edge e.
class Halfedge : public detail::BaseHandle<detail::HalfedgeTag>
{
public:
    using BaseHandle::BaseHandle;
};

//! An unoriented edge (a strut).
class Edge : public detail::BaseHandle<detail::EdgeTag>
{
public:
    using BaseHandle::BaseHandle;
};

//! A polygonal face.
class Face : public detail::BaseHandle<detail::FaceTag>
{
public:
    using BaseHandle::BaseHandle;
};

//! Streams handles as v12, h7, e3, f0 (or v-, h-, ... when invalid).
std::ostream& operator<<(std::ostream& os, Vertex v);
std::ostream& operator<<(std::ostream& os, Halfedge h);
std::ostream& operator<<(std::ostream& os, Edge e);
std::ostream& operator<<(std::ostream& os, Face f);

} // namespace zomeify

//! Hashing of handles for unordered containers (the index itself; indices are dense and distinct).
template <>
struct std::hash<zomeify::Vertex>
{
    size_t operator()(zomeify::Vertex h) const noexcept { return h.idx(); }
};
template <>
struct std::hash<zomeify::Halfedge>
{
    size_t operator()(zomeify::Halfedge h) const noexcept { return h.idx(); }
};
template <>
struct std::hash<zomeify::Edge>
{
    size_t operator()(zomeify::Edge h) const noexcept { return h.idx(); }
};
template <>
struct std::hash<zomeify::Face>
{
    size_t operator()(zomeify::Face h) const noexcept { return h.idx(); }
};
