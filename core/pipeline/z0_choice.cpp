#include "core/pipeline/z0_choice.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "core/voxel/facing_gaps.h"

namespace zomeify {

InitialModelOptions run_z0_options(const SurfaceProjector& projector, long long genus, int resolution, double b1)
{
    InitialModelOptions o;
    o.resolution = resolution;
    o.b1 = b1;
    // A grid a few percent off (a nudge), or the grid carved freely, often keeps a handle the exact
    // grid closes or bridges.
    o.target_genus = genus;
    o.surface_probe = probe_of(projector);
    return o;
}

AutoResolution automatic_resolution(const SurfaceProjector& projector, long long genus, const InsidePredicate& inside)
{
    AutoResolutionOptions options;
    options.initial = run_z0_options(projector, genus, 0, 0.0);
    // Gaps up to a cell of the coarsest grid searched for them matter.
    const auto box = bounding_box(projector.mesh());
    const FacingGaps gaps =
        facing_gaps(projector, (box[1] - box[0]).maxCoeff() / std::max(1, options.preferred_resolution - 1));
    options.narrow_fraction = [&gaps](double width) { return gaps.fraction_narrower_than(width); };
    return choose_resolution(projector.mesh(), genus, inside, options);
}

std::string auto_resolution_json(const AutoResolution& a)
{
    nlohmann::json trials = nlohmann::json::array();
    for (const ResolutionTrial& t : a.trials)
        trials.push_back({t.resolution, t.valid ? t.genus : -1, t.balls});
    const nlohmann::json j = {{"resolution", a.resolution},
                              {"target_nodes", a.target_nodes},
                              {"balls", a.balls},
                              {"struts", a.struts},
                              {"size_cm", a.size_cm},
                              {"genus", a.genus},
                              {"surface_genus", a.surface_genus},
                              {"genus_kept", a.genus_kept},
                              {"preferred", a.preferred},
                              {"gap_resolution", a.gap_resolution},
                              {"narrow_at_preferred", a.narrow_at_preferred},
                              {"searched_from", a.searched_from},
                              {"searched_to", a.searched_to},
                              {"trials", trials},
                              {"message", a.message}};
    return j.dump();
}

} // namespace zomeify
