#pragma once
//! \file lattice_mirror.h
//! A mirror plane of the Zome lattice perpendicular to a coordinate axis (issue 41): the axes are
//! blue directions, and the reflection x_axis → 2c − x_axis maps the lattice onto itself exactly
//! when c is a lattice coordinate, so a model can be symmetric in exact coordinates.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/zome/model.h"
#include "core/zome/qphi.h"
#include "core/zome/zvec.h"

namespace zomeify {

struct LatticeMirror
{
    int axis = 0; //!< 0 = x, 1 = y, 2 = z
    //! The reflection maps twice-coordinate t (ZVec::twice) on the axis to sum − t: sum is four
    //! times the plane's coordinate (b0 = 1), so planes halfway between lattice layers fit too.
    QPhi sum = {};

    //! The plane whose twice-coordinate is `twice_plane`.
    static LatticeMirror through(int axis, QPhi twice_plane) { return {axis, twice_plane + twice_plane}; }
    //! The mirror image of p (exact).
    ZVec reflect(const ZVec& p) const;
    //! Whether p lies on the plane.
    bool on_plane(const ZVec& p) const { return p.twice(axis) + p.twice(axis) == sum; }
    //! The plane's coordinate on its axis (b0 = 1).
    double coordinate() const { return 0.25 * sum.to_double(); }
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

//! The ball each ball of the model maps to under the mirror; nothing when some ball has no image.
std::optional<std::vector<uint32_t>> mirror_ball_images(const ZomeModel& model, const LatticeMirror& mirror);

//! The plane across `axis` halfway between the model's extreme balls on it: the only plane across
//! that axis a model can map onto. The model must have balls.
LatticeMirror middle_plane(const ZomeModel& model, int axis);

//! A model's own mirror symmetry about a plane perpendicular to an axis: for each axis the only
//! candidate is the plane halfway between the model's extreme balls on it; the best of the three
//! (fewest balls, then struts, without an image). Empty for a model without balls.
struct ModelMirror
{
    LatticeMirror mirror;
    MirrorMismatch mismatch;
};
std::optional<ModelMirror> model_mirror(const ZomeModel& model);

} // namespace zomeify
