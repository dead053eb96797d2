#pragma once
//! \file local_change.h
//! LocalChange: an operator's proposal as the energy sees it (design.md §3.3): the mesh elements
//! that disappear (handles into the current mesh) and the elements that appear (exact positions).
//! Nothing else needs describing: corners come with their faces, and the nodes whose 1-ring
//! changes are exactly the endpoints of removed and added struts, which the energy derives.
//!
//! Rules for a consistent description (check_change() verifies them in tests and debug runs):
//!  - each element is listed once;
//!  - a removed node's struts and faces are all removed, and so is every face of a removed strut;
//!  - a moved node is a removed node plus an added node (with its struts and faces re-added);
//!  - added faces have 3 or 4 corners, counter-clockwise seen from outside;
//!  - an added strut or face corner is at an added node or at a surviving node that is a corner
//!    of a removed face or an endpoint of a removed strut (always so for a closed surface: new
//!    faces only fill the hole the removed faces leave).
//!
//! Fixed capacity, no allocation, noexcept: one object per thread is refilled for every proposal.
//! A full list refuses elements and sets overflowed(); such a proposal should be dropped.

#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "core/anneal/fixed_list.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

//! A face that an edit creates: 3 or 4 corners, counter-clockwise seen from outside.
struct NewFace
{
    std::array<ZVec, 4> corners{};
    uint8_t size = 0;
    std::span<const ZVec> view() const noexcept { return {corners.data(), size}; }
};

//! A strut that an edit creates.
struct NewStrut
{
    ZVec a, b;
};

class LocalChange
{
public:
    static constexpr size_t kMaxNodes = 8;   //!< removed, and added, nodes
    static constexpr size_t kMaxStruts = 64; //!< removed, and added, struts
    static constexpr size_t kMaxFaces = 64;  //!< removed, and added, faces

    //! Empties every list.
    void clear() noexcept;

    //! \name Elements that disappear (live elements of the current mesh)
    //!@{
    bool remove_node(Vertex v) noexcept { return removed_nodes_.push_back(v); }
    bool remove_strut(Edge e) noexcept { return removed_struts_.push_back(e); }
    bool remove_face(Face f) noexcept { return removed_faces_.push_back(f); }
    //! Removes v with all its struts and faces (its star).
    bool remove_star(const ZomeMesh& mesh, Vertex v) noexcept;
    //!@}

    //! \name Elements that appear
    //!@{
    bool add_node(const ZVec& p) noexcept { return added_nodes_.push_back(p); }
    bool add_strut(const ZVec& a, const ZVec& b) noexcept { return added_struts_.push_back({a, b}); }
    //! A face of 3 or 4 corners (anything else is refused and counts as an overflow).
    bool add_face(std::span<const ZVec> corners) noexcept;
    bool add_triangle(const ZVec& a, const ZVec& b, const ZVec& c) noexcept;
    bool add_quad(const ZVec& a, const ZVec& b, const ZVec& c, const ZVec& d) noexcept;
    //!@}

    //! Whether some element was refused since clear().
    bool overflowed() const noexcept;

    const FixedList<Vertex, kMaxNodes>& removed_nodes() const noexcept { return removed_nodes_; }
    const FixedList<Edge, kMaxStruts>& removed_struts() const noexcept { return removed_struts_; }
    const FixedList<Face, kMaxFaces>& removed_faces() const noexcept { return removed_faces_; }
    const FixedList<ZVec, kMaxNodes>& added_nodes() const noexcept { return added_nodes_; }
    const FixedList<NewStrut, kMaxStruts>& added_struts() const noexcept { return added_struts_; }
    const FixedList<NewFace, kMaxFaces>& added_faces() const noexcept { return added_faces_; }

private:
    FixedList<Vertex, kMaxNodes> removed_nodes_;
    FixedList<Edge, kMaxStruts> removed_struts_;
    FixedList<Face, kMaxFaces> removed_faces_;
    FixedList<ZVec, kMaxNodes> added_nodes_;
    FixedList<NewStrut, kMaxStruts> added_struts_;
    FixedList<NewFace, kMaxFaces> added_faces_;
    bool bad_face_ = false;
};

//! Checks the rules above against the mesh the change applies to. Returns an empty string when
//! the description is consistent, otherwise the first problem found. O(size of the change ×
//! valence); allocates; meant for tests and debug checks, not the annealing loop.
std::string check_change(const ZomeMesh& mesh, const LocalChange& change);

} // namespace zomeify
