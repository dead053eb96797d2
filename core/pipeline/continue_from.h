#pragma once
//! \file continue_from.h
//! Working on a model that exists (paper §6): `run --from MODEL` anneals from it instead of Z0,
//! with the run's options; `--near X,Y,Z --radius R` changes only the part of it near a point.
//! A model continued on a surface must have been made for it: its transform places it there.

#include <array>
#include <optional>
#include <string>

#include "core/anneal/engine/anneal_options.h"
#include "core/geom/closest_point.h"
#include "core/geom/triangle_mesh.h"
#include "core/zome/model.h"

namespace zomeify {

//! A point of the surface and a radius, mesh units: the spot to fix.
struct FixSpot
{
    Vec3 centre = Vec3::Zero();
    double radius = 0.0;
};

//! T0's factor for a continued run (AnnealOptions::t0_spread_factor): cooler than a run from Z0,
//! so that the model is refined, not first taken apart (continue_from.cpp says how it was chosen).
inline constexpr double kContinueT0Factor = 0.01;
//! A fix (PipelineOptions::fix) starts cooler still, and weighs the distance term more (the paper
//! tightens the forbidden zone there; only the spot can change, so the weight acts there alone).
inline constexpr double kFixT0Factor = 0.003;
inline constexpr double kFixDistanceWeightFactor = 3.0;

//! The ways a fix is tried, each on a third of the budget (pipeline.cpp fix_spot): the gap a spot
//! shows responds to one or another depending on the shape there (continue_from.cpp).
struct FixAttempt
{
    double t0_factor;
    bool raise_target; //!< fix_target(), else the model's own count
};
inline constexpr std::array<FixAttempt, 3> kFixAttempts = {{{kFixT0Factor, true}, {0.04, true}, {0.04, false}}};
//! Points on each side measured for the largest gap within the spot.
inline constexpr int kFixGapSamples = 60000;

//! Why `model` cannot be continued on the surface of `projector`, in one line; "" when it can.
//! Refused: no nodes, or nodes that do not lie on the surface in mesh units (a model made for
//! another mesh, or for this mesh at another scale, or one whose transform was lost).
std::string model_fit_problem(const ZomeModel& model, const SurfaceProjector& projector);

//! Whether a continued run stopped short of its ball target: more than 10 % (and 3 balls) away
//! from it in the direction asked (the paper's saturation point of a decimation).
bool short_of_target(size_t start, size_t target, size_t reached);

//! The surface's capacity (issue 40, More detail): at a fixed size a surface holds only so many
//! balls well; past that, more balls make the model crumple (the paper's fold-overs) and fit worse.
//! Measured as the surface's area in b0² over the area one ball of the best-fitting models takes
//! (calibrated on three meshes: continue_from.cpp and docs/work-on-a-model.md give the figures).
inline constexpr double kAreaPerBallB0Squared = 0.8;

//! The area of a triangle mesh (mesh units²).
double surface_area(const TriangleMesh& mesh);

//! About how many balls a surface of `area` (mesh units²) holds well with b0 = `b0_length` mesh
//! units: area / b0² / kAreaPerBallB0Squared, rounded, at least 4 (the core's least model).
size_t surface_capacity(double area, double b0_length);

//! The same for `surface` at the scale of a model placed by `transform` (b0 = the B0 strut's
//! length × transform.scale); 0 when the transform has no scale.
size_t surface_capacity(const TriangleMesh& surface, const ModelTransform& transform);

//! A continued run's sentence when its ball target was lowered to the capacity.
std::string capacity_capped_text(size_t capacity);

//! Why a model of `balls` balls gets no more balls at its size (at_capacity()), in one line.
std::string capacity_full_text(size_t balls, size_t capacity);

//! A model of `balls` balls has the capacity (0: unknown, never): it has at least the capacity less
//! 3 % of it (and 3 balls); a step capped at the capacity from there adds almost nothing (the bunny
//! at the paper's size: 509 balls against 510 stayed 509 in three capped steps).
bool at_capacity(size_t balls, size_t capacity);

//! A continued run's ball target against the capacity (0: unknown, no bound): `target` when it
//! asks for no more balls than the model has or than the capacity, else the capacity; throws
//! InvalidInputError (capacity_full_text) when it asks for more and the model is at_capacity().
size_t capped_target(size_t balls, size_t target, size_t capacity);

//! The spot in the model's own units.
ChangeRegion region_of(const FixSpot& spot, const ModelTransform& transform);

//! How many nodes of `model` lie inside `region`.
size_t nodes_in_region(const ZomeModel& model, const ChangeRegion& region);

//! The ball target of a fix when none is given: the model's count plus half the nodes of the spot
//! (at least 4), as the paper raises N_target there.
size_t fix_target(const ZomeModel& model, const ChangeRegion& region);

} // namespace zomeify
