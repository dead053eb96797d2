#pragma once
//! \file fill.h
//! The common last step of every operator (paper §5.1, design.md §3.4): the removed faces leave a
//! hole bounded by the link, an oriented simple loop of surviving nodes; the operator proposes a
//! new disc of faces over that loop (a Fill), and complete_fill() checks it against the Zome rules
//! and writes it into the LocalChange.
//!
//! Why this keeps the surface a closed 2-manifold of the same genus: the removed faces form a disc
//! (a face, the two faces of a strut, or the faces around a node, whose link is a simple loop),
//! and the fill is a disc with the same boundary whose interior edges are new struts that no
//! surviving strut duplicates. Cutting out a disc and gluing in a disc changes neither the
//! manifoldness nor the Euler characteristic.
//!
//! Internal to core/anneal/operators.

#include <array>
#include <cstdint>

#include "core/anneal/energy/local_change.h"
#include "core/anneal/fixed_list.h"
#include "core/anneal/node_claims.h"
#include "core/anneal/proposal.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify::detail {

//! Links of up to this many nodes (a node has at most 62 struts, a link rarely more than 12).
inline constexpr size_t kMaxLink = 48;
inline constexpr size_t kMaxFillNodes = kMaxLink + 1;

//! A corner of the fill: a surviving link node, or (v invalid) the node the change adds.
struct FillNode
{
    Vertex v;
    ZVec pos;
};

//! A face of the fill: indices into Fill::nodes, counter-clockwise seen from outside.
struct FillFace
{
    std::array<uint8_t, 4> corners{};
    uint8_t size = 0;
};

class Fill
{
public:
    void clear() noexcept
    {
        nodes_.clear();
        faces_.clear();
        link_size_ = 0;
    }
    //! Appends the next node of the link (all link nodes come before any new node).
    bool add_link_node(const ZomeMesh& mesh, Vertex v) noexcept
    {
        link_size_ = nodes_.size() + 1;
        return nodes_.push_back({v, mesh.position(v)});
    }
    //! Appends a node the change adds; returns its index (or -1 when full).
    int add_new_node(const ZVec& p) noexcept
    {
        return nodes_.push_back({Vertex(), p}) ? static_cast<int>(nodes_.size() - 1) : -1;
    }
    bool add_triangle(size_t a, size_t b, size_t c) noexcept { return add_face({a, b, c, 0}, 3); }
    bool add_quad(size_t a, size_t b, size_t c, size_t d) noexcept { return add_face({a, b, c, d}, 4); }
    //! The face (centre, link[from], link[from+1], ..., link[to]) with link indices taken cyclically.
    bool add_fan_face(size_t centre, size_t from, size_t to) noexcept;
    //! Whether no link node occurs twice ("a node pointed to twice", paper §5.1).
    bool link_is_simple() const noexcept;
    //! Whether (a, b) is an edge of the link in its orientation.
    bool is_link_edge(size_t a, size_t b) const noexcept
    {
        return a < link_size_ && b < link_size_ && b == (a + 1) % link_size_;
    }

    size_t link_size() const noexcept { return link_size_; }
    const FixedList<FillNode, kMaxFillNodes>& nodes() const noexcept { return nodes_; }
    const FixedList<FillFace, LocalChange::kMaxFaces>& faces() const noexcept { return faces_; }
    bool overflowed() const noexcept { return nodes_.overflowed() || faces_.overflowed(); }

private:
    bool add_face(std::array<size_t, 4> c, uint8_t size) noexcept;

    FixedList<FillNode, kMaxFillNodes> nodes_;
    FixedList<FillFace, LocalChange::kMaxFaces> faces_;
    size_t link_size_ = 0;
};

//! Claims v for the proposal: None, Busy (another thread holds it) or Overflow (claims full).
Rejection claim(Claims& claims, Vertex v) noexcept;

//! Whether v keeps a strut in `slot` that the change does not remove.
bool keeps_strut_in_slot(const ZomeMesh& mesh, Vertex v, int slot, const LocalChange& change) noexcept;

//! Whether a node may be added at p: no node there, or only one the change removes.
bool position_usable(const ZomeMesh& mesh, const LocalChange& change, const ZVec& p) noexcept;

//! Checks the fill of the hole that `change`'s removed elements leave and, when it is valid, adds
//! its nodes, struts and faces to `change` and claims the 1-rings of every surviving node whose
//! struts change (the energy's fairing reads them). The checks: every link edge used once and
//! every new strut by two faces in opposite directions (a disc), every new strut a Zome vector,
//! no two struts in one slot of a node (which also rules out a second strut between two nodes),
//! valence ≥ 3, and every new position free (a removed node's own position counts as free).
Rejection complete_fill(const ZomeMesh& mesh, const Fill& fill, Claims& claims, LocalChange& change) noexcept;

} // namespace zomeify::detail
