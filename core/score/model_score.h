#pragma once
//! \file model_score.h
//! How good a Zome model is against an input surface S, measured the same way for any model
//! (ours, or the paper's published one): the energy terms of design.md §3.3, fold-overs, and the
//! symmetric distance between the model's faces and S (all lengths in b0).

#include <array>
#include <optional>
#include <string>

#include "core/anneal/energy/energy_options.h"
#include "core/anneal/energy/energy_sums.h"
#include "core/anneal/rules/clearance_index.h"
#include "core/geom/closest_point.h"
#include "core/score/fidelity.h"
#include "core/score/fold_over_report.h"
#include "core/zome/lattice_mirror.h"
#include "core/zome/model.h"
#include "core/zome/slots.h"

namespace zomeify {

struct ModelScore
{
    size_t nodes = 0, struts = 0, faces = 0, triangles = 0, quads = 0;
    std::array<size_t, kStrutKindCount> struts_by_kind{};
    int genus = 0;
    EnergyTerms energy;        //!< with target_nodes = the model's own node count unless given
    FoldOverReport fold_overs; //!< faces whose normal points against S's normal at π(barycentre), and where
    Fidelity fidelity;         //!< distances both ways, in b0 (fidelity.h)
    ClearanceReport clearance; //!< clashes between parts and the smallest clearances
    //! The model's own mirror symmetry (lattice_mirror.h: the best plane across an axis, and what has
    //! no image about it); `mirror_at` is that plane's coordinate in mesh units.
    std::optional<ModelMirror> mirror;
    double mirror_at = 0.0;
};

//! "maps onto itself about x = 0.25 (every ball and strut has its mirror image)", or how far it is.
std::string mirror_summary(const ModelScore& score);

struct ScoreOptions
{
    EnergyOptions energy; //!< energy.target_nodes = 0 → the model's node count
    FidelityOptions fidelity;
};

//! Scores a model with faces (counter-clockwise from outside) placed on S by model.transform.
//! Throws InvalidInputError if the model has no faces or is not a closed Zome surface.
ModelScore score_model(const ZomeModel& model, const SurfaceProjector& surface, const ScoreOptions& options = {});

//! The score as a JSON object.
std::string score_json(const ModelScore& score);

} // namespace zomeify
