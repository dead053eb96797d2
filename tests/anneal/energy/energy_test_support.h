#pragma once
//! \file energy_test_support.h
//! Scenes for the energy tests: an input surface S placed relative to a Zome model through a
//! non-trivial model transform, with the projector and the energy's SurfaceContext.

#include <array>
#include <memory>

#include "core/anneal/energy/surface_context.h"
#include "core/geom/closest_point.h"
#include "core/zome/model.h"

namespace zomeify::test {

//! The projector of S and the context built on it (the context refers to the projector).
struct EnergyScene
{
    std::unique_ptr<SurfaceProjector> projector;
    std::unique_ptr<SurfaceContext> context;
};

//! A scale and translation far from the identity, so unit conversions are exercised.
ModelTransform energy_test_transform();

//! Builds the scene for a surface given in Zome units, mapped into mesh units by `transform`.
EnergyScene make_energy_scene(TriangleMesh surface_in_zome_units, const ModelTransform& transform);

//! Min and max corner of the model's nodes (Zome units).
std::array<Vec3, 2> node_bounds(const ZomeModel& model);

//! An icosphere (3 subdivisions) around the centre of the model's nodes, with a radius of 0.45
//! of the largest box side: some samples inside S, some outside, at distances spanning both
//! forbidden zones.
EnergyScene sphere_scene_for(const ZomeModel& model, const ModelTransform& transform);

} // namespace zomeify::test
