// The --stats object of `zomeify run` (design.md §5), shared with the page's run summary.
#include <map>

#include <nlohmann/json.hpp>

#include "core/pipeline/pipeline.h"
#include "core/pipeline/z0_choice.h"
#include "core/zome/slots.h"

namespace zomeify {

namespace {

nlohmann::json terms_json(const EnergyTerms& t)
{
    return {{"total", t.total},           {"distance", t.distance},  {"orientation", t.orientation},
            {"tangential", t.tangential}, {"normal", t.normal},      {"fairing", t.fairing},
            {"complexity", t.complexity}, {"surface", t.surface},    {"fold_overs", t.sums.fold_overs},
            {"nodes", t.sums.nodes},      {"struts", t.sums.struts}, {"faces", t.sums.faces}};
}

nlohmann::json clearance_json(const ClearanceReport& c)
{
    nlohmann::json kinds = nlohmann::json::object();
    for (int k = 1; k < kClashKinds; ++k)
        kinds[clash_name(static_cast<ClashKind>(k))] = c.clashes[static_cast<size_t>(k)];
    return {{"clashes", c.total()},
            {"by_kind", kinds},
            {"smallest_b0", {{"ball_ball", c.ball_ball}, {"ball_strut", c.ball_strut}, {"strut_strut", c.strut_strut}}},
            {"summary", clearance_summary(c)}};
}

nlohmann::json struts_by_kind(const ZomeModel& m)
{
    std::map<std::string, size_t> counts;
    for (int k = 0; k < kStrutKindCount; ++k)
        counts[std::string(kind_info(static_cast<StrutKind>(k)).name)] = 0;
    for (const auto& s : m.struts)
    {
        if (s[0] >= m.nodes.size() || s[1] >= m.nodes.size())
            continue;
        const int id = vector_id_of(m.nodes[s[1]] - m.nodes[s[0]]);
        if (id >= 0)
            ++counts[std::string(kind_info(vector_kind(id)).name)];
    }
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [k, n] : counts)
        j[k] = n;
    return j;
}

nlohmann::json anneal_json(const AnnealResult& a)
{
    const AnnealStats& s = a.stats;
    nlohmann::json ops = nlohmann::json::object();
    for (int k = 0; k < kOperatorKinds; ++k)
    {
        const OperatorCounts& c = s.per_operator[k];
        ops[std::string(operator_name(static_cast<OperatorKind>(k)))] = {
            {"proposed", c.proposed}, {"valid", c.valid}, {"accepted", c.accepted}};
    }
    nlohmann::json rejections = nlohmann::json::object();
    for (int r = 1; r < kRejectionKinds; ++r)
        rejections[std::string(rejection_name(static_cast<Rejection>(r)))] = s.rejections[r];
    return {{"seconds", s.wall_seconds},
            {"valid_proposals", s.valid_proposals},
            {"acceptance_rate", s.valid_proposals ? static_cast<double>(s.commits) / s.valid_proposals : 0.0},
            {"initial_temperature", s.initial_temperature},
            {"min_temperature", s.min_temperature},
            {"t0_valid_samples", s.t0_valid_samples},
            {"cancelled", s.cancelled},
            {"operators", ops},
            {"rejections", rejections},
            {"busy_seeds", s.busy_seeds},
            {"dead_seeds", s.dead_seeds},
            {"lost_races", s.lost_races},
            {"redecisions", s.redecisions},
            {"commit_hold_seconds", s.commit_hold_seconds},
            {"commit_wait_seconds", s.commit_wait_seconds},
            {"fold_over_repair",
             {{"before", s.fold_overs_before_repair},
              {"after", s.fold_overs_after_repair},
              {"proposals", s.repair_proposals},
              {"commits", s.repair_commits}}},
            {"garbage_collections", s.garbage_collections},
            {"coverage",
             {{"radius_b0", s.coverage_radius},
              {"samples", s.coverage_samples},
              {"uncovered_at_start", s.uncovered_at_start},
              {"uncovered_at_end", s.uncovered_at_end}}},
            {"energy_sums_consistent", s.energy_consistent},
            {"best_energy", a.best.total}};
}

} // namespace

std::string pipeline_stats_json(const PipelineResult& r, int indent)
{
    const InitialModelReport& z0 = r.initial.report;
    nlohmann::json j;
    j["stage"] = r.anneal ? "annealed" : "initial";
    j["wall_seconds"] = r.seconds;
    j["threads"] = r.anneal ? r.anneal->stats.threads : 1;
    const uint64_t proposals = r.anneal ? r.anneal->stats.proposals : 0;
    const uint64_t commits = r.anneal ? r.anneal->stats.commits : 0;
    j["proposals"] = proposals;
    j["commits"] = commits;
    j["proposals_per_second"] = r.anneal ? r.anneal->stats.proposals_per_second : 0.0;
    j["commits_per_second"] = r.anneal ? r.anneal->stats.commits_per_second : 0.0;
    j["N"] = r.model.nodes.size();
    j["struts"] = r.model.struts.size();
    j["faces"] = r.model.faces.size();
    j["struts_by_kind"] = struts_by_kind(r.model);
    j["genus_surface"] = r.surface_genus;
    j["genus_model"] = r.model_genus;
    j["valid"] = r.model_valid;
    j["fold_overs"] = r.fold_overs.count();
    j["fold_over_places"] = fold_over_places_json(r.fold_overs);
    j["clearance"] = clearance_json(r.clearance);
    if (r.model_valid)
        j["fidelity"] = fidelity_json(r.fidelity);
    j["energy"] = {{"start", terms_json(r.anneal ? r.anneal->start : r.model_energy)},
                   {"end", terms_json(r.model_energy)}};
    if (r.anneal)
        j["anneal"] = anneal_json(*r.anneal);
    j["resolution"] = r.resolution;
    j["b1_mesh_units"] = z0.grid.cell;
    j["capacity"] = r.capacity;
    j["initial"] = {{"N", r.initial.model.nodes.size()},
                    {"struts", r.initial.model.struts.size()},
                    {"faces", r.initial.model.faces.size()},
                    {"genus", z0.topology.genus},
                    {"components", z0.topology.components},
                    {"grid", z0.grid.dims},
                    {"voxels", z0.voxels},
                    {"grid_attempts", z0.attempts},
                    {"grid_used", z0.attempt_used},
                    {"cell_scale_factor", z0.layout.scale_factor},
                    {"cleanup_removed", z0.repair.removed},
                    {"cleanup_added", z0.repair.added},
                    {"cavity_cells_filled", z0.voxelize.cavity_cells},
                    {"carved", z0.carve.removed - z0.carve.restored},
                    {"carve_kept_for_thin_parts", z0.carve.kept_for_coverage},
                    {"carve_restored_for_fold_overs", z0.carve.restored},
                    {"carve_topology", z0.centre_sampled                          ? "centre"
                                       : z0.carve_topology == CarveTopology::Free ? "free"
                                                                                  : "keep"},
                    {"grids_missed", z0.notes},
                    {"seconds", r.initial_seconds}};
    if (r.kit_estimate)
        j["kit_estimate"] = {{"kits", kits_text(r.kit_estimate->plan.kits)},
                             {"typically", kits_text(plan_kits(r.kit_estimate->quick).kits)},
                             {"quick_pass_proposals", kQuickPassProposals},
                             {"seconds", r.kit_estimate->seconds}};
    if (r.mirror)
    {
        j["mirror"] = nlohmann::json::parse(mirror_choice_json(*r.mirror));
        if (r.mirror->used)
            j["mirror"]["model"] = {{"balls_without_image", r.mirror_mismatch.balls},
                                    {"struts_without_image", r.mirror_mismatch.struts},
                                    {"symmetric", r.mirror_mismatch.symmetric()}};
    }
    if (r.continued)
    {
        j["continued"] = {
            {"from_balls", r.initial.model.nodes.size()},
            {"from_struts", r.initial.model.struts.size()},
            {"kept_as_it_was", r.kept_start},
            {"target_nodes", r.target_nodes},
            {"short_of_target", short_of_target(r.initial.model.nodes.size(), r.target_nodes, r.model.nodes.size())},
            {"capacity", r.capacity},
            {"capped", r.capped}};
        if (r.capped)
        {
            j["continued"]["asked_nodes"] = r.asked_nodes;
            j["continued"]["capacity_note"] = capacity_capped_text(r.capacity);
        }
        if (r.region)
            j["continued"]["region"] = {{"centre", r.region->centre},
                                        {"radius", r.region->radius},
                                        {"balls", nodes_in_region(r.initial.model, *r.region)},
                                        {"largest_gap_b0_before", r.spot_gap_before},
                                        {"largest_gap_b0_after", r.spot_gap_after}};
    }
    if (!r.advice.empty())
        j["advice"] = r.advice;
    if (r.automatic)
    {
        j["automatic_resolution"] = nlohmann::json::parse(auto_resolution_json(*r.automatic));
        j["automatic_resolution"]["seconds"] = r.automatic->seconds;
    }
    return j.dump(indent);
}

} // namespace zomeify
