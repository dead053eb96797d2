#include "core/pipeline/z0_choice.h"

#include <nlohmann/json.hpp>

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
                              {"searched_from", a.searched_from},
                              {"searched_to", a.searched_to},
                              {"trials", trials},
                              {"message", a.message}};
    return j.dump();
}

} // namespace zomeify
