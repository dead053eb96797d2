#pragma once
//! \file symmetry.h
//! The 60 rotations of the icosahedral group that map the 186 Zome vectors onto themselves.
//! Found by search, not typed in: every candidate frame (two orthogonal blue unit vectors and
//! their cross product) is kept when it maps the whole vector set onto itself.

#include <array>
#include <optional>
#include <vector>

#include "core/zome/slots.h"

namespace zomeify {

struct Rotation
{
    //! Columns are the images of the x, y and z unit vectors (b0 blue vectors).
    std::array<ZVec, 3> columns;
    //! slot_map[s] is the slot that slot s is rotated to.
    std::array<uint8_t, kSlotCount> slot_map;

    //! The rotated vector, or nothing if it leaves the 6-integer lattice (never for lattice
    //! points reachable by struts).
    std::optional<ZVec> apply(const ZVec& v) const;
};

//! The 60 rotations; the identity first.
const std::vector<Rotation>& zome_rotations();

//! Exact cross product, or nothing if the result is not in the 6-integer form.
std::optional<ZVec> cross(const ZVec& u, const ZVec& v);

} // namespace zomeify
