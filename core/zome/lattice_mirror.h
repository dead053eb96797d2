#pragma once
//! \file lattice_mirror.h
//! A mirror plane of the Zome lattice perpendicular to a coordinate axis (issue 41): the axes are
//! blue directions, and the reflection x_axis → 2c − x_axis maps the lattice onto itself exactly
//! when c is a lattice coordinate, so a model can be symmetric in exact coordinates.

#include <cstddef>

#include "core/zome/model.h"
#include "core/zome/qphi.h"
#include "core/zome/zvec.h"

namespace zomeify {

struct LatticeMirror
{
    int axis = 0;          //!< 0 = x, 1 = y, 2 = z
    QPhi twice_plane = {}; //!< twice the plane's coordinate on that axis (b0 = 1, as ZVec::twice)

    //! The mirror image of p (exact).
    ZVec reflect(const ZVec& p) const;
    //! Whether p lies on the plane.
    bool on_plane(const ZVec& p) const { return p.twice(axis) == twice_plane; }
    //! The plane's coordinate on its axis (b0 = 1).
    double coordinate() const { return 0.5 * twice_plane.to_double(); }
    friend bool operator==(const LatticeMirror&, const LatticeMirror&) = default;
};

//! How far a model is from mapping onto itself under a mirror: balls and struts whose mirror image
//! is not a ball, or not a strut, of the model. Both 0: the model is exactly symmetric.
struct MirrorMismatch
{
    size_t balls = 0;
    size_t struts = 0;
    bool symmetric() const { return balls == 0 && struts == 0; }
};
MirrorMismatch mirror_mismatch(const ZomeModel& model, const LatticeMirror& mirror);

} // namespace zomeify
