// Proposals per second of each operator kind, without and with ΔE (propose() + simulate +
// delta_energy), on Z0 of the shared torus after 2000 random applications (a mix of triangles,
// quads and valences), with the default projection cache and one that holds every sample.
// Was the GoogleTest case OperatorEnergy.ProposalRatePerKind: a timing run belongs with the
// benchmarks. The lines as before on stderr, one JSON object on stdout.
#include <array>
#include <chrono>
#include <cstdio>
#include <string>

#include "core/anneal/energy/energy_state.h"
#include "core/anneal/operators/operators.h"
#include "core/mesh/model_convert.h"
#include "tests/anneal/operators/operator_test_support.h"
#include "tests/bench/bench_util.h"

namespace zomeify {
namespace {

EnergyOptions options_for(size_t nodes)
{
    EnergyOptions o;
    o.target_nodes = nodes;
    return o;
}

// A quick figure, printed and not asserted: propose() + simulate + delta_energy per kind on Z0
// of the torus after 2000 random applications (a mix of triangles, quads and valences), with a
// projection cache of `cache_capacity` entries; the per-kind rates as a JSON object.
std::string print_rates(size_t cache_capacity)
{
    ProjectionCacheOptions cache;
    cache.capacity = cache_capacity;
    const test::SharedScene scene = test::shared_scene("torus.obj", 12, cache);
    ZomeMesh mesh = from_model(scene.z0);
    Rng rng(5);
    Proposal p;
    for (int applied = 0; applied < 2000;)
    {
        const auto kind = static_cast<OperatorKind>(rng.below(kOperatorKinds));
        if (test::propose_at(kind, mesh, test::random_node(mesh, rng), rng, p))
        {
            apply_proposal(mesh, p);
            ++applied;
        }
    }
    mesh.garbage_collection();
    const EnergyOptions options = options_for(mesh.n_vertices());
    const EnergyState state(mesh, *scene.context, options);
    constexpr int kProposals = 20000;
    // Pass 0 warms the projection cache (the same proposals come back: every pass of a kind
    // uses the same random stream); pass 1 times propose() alone, pass 2 with ΔE.
    std::array<double, kOperatorKinds> propose_rate{};
    std::string json = "{\"cache\": " + std::to_string(cache_capacity) +
                       ", \"nodes\": " + std::to_string(mesh.n_vertices()) + ", \"kinds\": {";
    std::fprintf(stderr,
                 "[ rate     ] %zu nodes, projection cache of %zu; per kind: proposals/s without and with ΔE "
                 "(valid share)\n",
                 mesh.n_vertices(), cache_capacity);
    for (int pass = 0; pass < 3; ++pass)
    {
        for (int k = 0; k < kOperatorKinds; ++k)
        {
            const auto kind = static_cast<OperatorKind>(k);
            Rng r(static_cast<uint64_t>(k));
            int valid = 0;
            double sink = 0.0;
            const auto t0 = std::chrono::steady_clock::now();
            for (int i = 0; i < kProposals; ++i)
            {
                Claims claims;
                const Vertex seed = test::random_node(mesh, r);
                claims.take(seed);
                if (propose(kind, mesh, seed, r, claims, p))
                {
                    ++valid;
                    if (pass != 1)
                        sink += state.delta_energy(state.simulate(mesh, p.change));
                }
            }
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            if (pass == 1)
                propose_rate[static_cast<size_t>(k)] = kProposals / s;
            if (pass == 2)
            {
                char line[160];
                std::snprintf(line, sizeof line,
                              "%s\"%s\": {\"propose_per_s\": %.0f, \"with_delta_per_s\": %.0f, \"valid\": %.4f}",
                              k ? ", " : "", std::string(operator_name(kind)).c_str(),
                              propose_rate[static_cast<size_t>(k)], kProposals / s,
                              static_cast<double>(valid) / kProposals);
                json += line;
                std::fprintf(stderr, "[ rate     ] %-10s %9.0f /s %9.0f /s  (%4.1f%% valid)%s\n",
                             std::string(operator_name(kind)).c_str(), propose_rate[static_cast<size_t>(k)],
                             kProposals / s, 100.0 * valid / kProposals, sink == 12345.0 ? " " : "");
            }
        }
    }
    return json + "}}";
}

} // namespace
} // namespace zomeify

int main(int argc, char** argv)
{
    return zomeify::bench::guarded_main(argc, argv, [](int, char**) {
        const std::string by_default = zomeify::print_rates(zomeify::ProjectionCacheOptions().capacity);
        const std::string all_fit = zomeify::print_rates(size_t{1} << 22); // every sample of the measurement fits
        std::printf("{\"bench\": \"operators\", \"platform\": \"%s\", \"default_cache\": %s, \"large_cache\": %s}\n",
                    zomeify::bench::platform().c_str(), by_default.c_str(), all_fit.c_str());
        return 0;
    });
}
