#include "core/score/model_score.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/anneal/energy/energy.h"
#include "core/anneal/energy/surface_context.h"
#include "core/base/errors.h"
#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"

namespace zomeify {
namespace {

} // namespace

ModelScore score_model(const ZomeModel& model, const SurfaceProjector& surface, const ScoreOptions& options)
{
    if (model.faces.empty())
        throw InvalidInputError("scoring needs the model's faces");
    const ZomeMesh mesh = from_model(model);
    const ValidationReport report = validate(mesh);
    if (!report.ok())
        throw InvalidInputError("the model is not a valid closed Zome surface: " + report.message());

    ModelScore score;
    score.nodes = model.nodes.size();
    score.struts = model.struts.size();
    score.faces = model.faces.size();
    score.genus = report.genus;
    for (const auto& f : model.faces)
        (f.size() == 3 ? score.triangles : score.quads) += 1;
    for (Edge e : edges(mesh))
        score.struts_by_kind[static_cast<size_t>(mesh.kind(e))] += 1;

    EnergyOptions energy = options.energy;
    if (energy.target_nodes == 0)
        energy.target_nodes = model.nodes.size();
    const SurfaceContext context(surface, model.transform);
    score.energy = evaluate_energy(mesh, context, energy);
    score.clearance = clearance_report(mesh);

    const SurfaceContext fold_context(surface, model.transform);
    score.fold_overs = fold_over_report(mesh, fold_context);
    score.fidelity = measure_fidelity(model, surface, options.fidelity);
    score.mirror = model_mirror(model);
    if (score.mirror)
        score.mirror_at = score.mirror->mirror.coordinate() * model.transform.scale +
                          model.transform.translation[static_cast<size_t>(score.mirror->mirror.axis)];
    return score;
}

std::string mirror_summary(const ModelScore& score)
{
    if (!score.mirror)
        return "no balls";
    const ModelMirror& m = *score.mirror;
    std::ostringstream s;
    s << std::setprecision(4);
    const char axis = "xyz"[m.mirror.axis];
    if (m.mismatch.symmetric())
        s << "maps onto itself about " << axis << " = " << score.mirror_at + 0.0 // + 0.0: "0", never "-0"
          << " (every ball and strut has its mirror image)";
    else
        s << "not mirror-symmetric: about the best plane across an axis (" << axis << " = " << score.mirror_at << "), "
          << m.mismatch.balls << " of " << score.nodes << " balls and " << m.mismatch.struts << " of " << score.struts
          << " struts have no mirror image";
    return s.str();
}

std::string score_json(const ModelScore& score)
{
    nlohmann::ordered_json j;
    j["nodes"] = score.nodes;
    j["struts"] = score.struts;
    nlohmann::ordered_json kinds;
    for (int k = 0; k < kStrutKindCount; ++k)
        kinds[std::string(kind_info(static_cast<StrutKind>(k)).name)] = score.struts_by_kind[static_cast<size_t>(k)];
    j["struts_by_kind"] = kinds;
    j["faces"] = {{"total", score.faces}, {"triangles", score.triangles}, {"quads", score.quads}};
    j["genus"] = score.genus;
    const EnergyTerms& e = score.energy;
    j["energy"] = {{"total", e.total},           {"distance", e.distance}, {"orientation", e.orientation},
                   {"tangential", e.tangential}, {"normal", e.normal},     {"fairing", e.fairing},
                   {"complexity", e.complexity}};
    j["fold_overs"] = score.fold_overs.count();
    j["fold_over_places"] = fold_over_places_json(score.fold_overs);
    const ClearanceReport& c = score.clearance;
    nlohmann::ordered_json clashes;
    for (int k = 1; k < kClashKinds; ++k)
        clashes[clash_name(static_cast<ClashKind>(k))] = c.clashes[static_cast<size_t>(k)];
    j["clearance"] = {
        {"clashes", c.total()},
        {"by_kind", clashes},
        {"smallest_b0", {{"ball_ball", c.ball_ball}, {"ball_strut", c.ball_strut}, {"strut_strut", c.strut_strut}}},
        {"summary", clearance_summary(c)}};
    j["fidelity"] = fidelity_json(score.fidelity);
    if (score.mirror)
        j["mirror"] = {{"axis", std::string(1, "xyz"[score.mirror->mirror.axis])},
                       {"at", score.mirror_at},
                       {"symmetric", score.mirror->mismatch.symmetric()},
                       {"balls_without_image", score.mirror->mismatch.balls},
                       {"struts_without_image", score.mirror->mismatch.struts},
                       {"summary", mirror_summary(score)}};
    return j.dump(2);
}

} // namespace zomeify
