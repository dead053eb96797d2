#pragma once
//! \file mirror_choice.h
//! Whether a run builds a mirror-symmetric model (`run --mirror auto`, issue 41), and on which
//! plane: the surface's best mirror plane (geom/mirror_plane.h) when it lies along a coordinate
//! axis of the mesh (the lattice's mirror planes through the B1 grid are perpendicular to its axes)
//! and the shape is symmetric about it within kMirrorToleranceB0 at the run's size.

#include <optional>
#include <string>

#include "core/geom/mirror_plane.h"
#include "core/voxel/mirror_cells.h"
#include "core/zome/lattice_mirror.h"

namespace zomeify {

enum class MirrorMode
{
    Off,  //!< the two halves are free (as before)
    Auto, //!< symmetric when the shape is (the tolerance below)
};

//! The largest RMS distance of the shape's mirror image from the shape, in b0 at the run's size,
//! for which a run is made symmetric (chosen by experiment: docs/mirror.md, "Measured").
inline constexpr double kMirrorToleranceB0 = 0.05;
//! How far the best plane's normal may lie from a coordinate axis (degrees) to be taken along it.
inline constexpr double kMirrorAxisDegrees = 3.0;

struct MirrorChoice
{
    MirrorMode mode = MirrorMode::Off;
    MirrorPlane found;                 //!< the surface's best plane, as found
    std::optional<AxisPlane> along;    //!< that plane snapped to an axis, when it is close to one
    MirrorPlane measured;              //!< the shape's symmetry about `along` (or `found`), mesh units
    double b0 = 0.0;                   //!< b0 of the run in mesh units
    bool symmetric = false;            //!< along an axis and within the tolerance
    std::optional<LatticeMirror> used; //!< the run was annealed symmetric about this lattice plane
    std::string message;               //!< one line: what was decided and why
};

//! The choice for a surface at a run's b0 (mesh units); `used` is left for the pipeline to set once
//! a symmetric Z0 exists.
MirrorChoice choose_mirror(const SurfaceProjector& surface, double b0);

//! The plane in mesh units of a lattice mirror under a model transform (model → mesh: x·scale + t).
AxisPlane mesh_plane(const LatticeMirror& mirror, const ModelTransform& transform);

//! The choice as a JSON object (--stats "mirror", the page): mode, normal, offset, rms_b0, rms_mm,
//! max_mm, symmetric, used, axis, at, message.
std::string mirror_choice_json(const MirrorChoice& choice);

} // namespace zomeify
