// ΔE evaluations per second: EnergyState::simulate (the local sums of a proposal) plus
// delta_energy (ΔE from the global sums) for random local changes (ADDDIAG, REMDIAG, FLIPDIAG,
// MOVNODE, INSNODE, REMNODE) on Z0 of a shared mesh at about 400 nodes, after N/2 random edits. Reported with a cold
// projection cache (one pass right after clearing it) and a warm one, on 1 and 2 threads, per
// operator kind, next to the time of one full evaluate_energy. Prints one JSON object.
// Usage: bench_energy [mesh.obj [target_nodes]]   (mesh relative to the shared meshes folder)
#include <cstdlib>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/anneal/energy/energy_state.h"
#include "core/geom/inside.h"
#include "core/mesh/model_convert.h"
#include "core/surface/prepare.h"
#include "core/voxel/initial_model.h"
#include "tests/anneal/energy/energy_edits.h"
#include "tests/bench/bench_util.h"

using namespace zomeify;

namespace {

constexpr int kRuns = 5;
constexpr size_t kProposals = 2000;
constexpr int kPasses = 20;

// Z0 at the resolution (6..16 cells along the longest side) whose node count is closest to target.
InitialModel z0_near(const TriangleMesh& surface, const InsideTest& inside, size_t target)
{
    InitialModel best;
    size_t best_gap = SIZE_MAX;
    for (int resolution = 6; resolution <= 16; ++resolution)
    {
        InitialModelOptions options;
        options.resolution = resolution;
        InitialModel z0 = build_initial_model(
            surface, [&](const Vec3& p) { return inside.is_inside(p); }, options);
        if (!z0.report.valid)
        {
            continue;
        }
        const size_t n = z0.model.nodes.size();
        const size_t gap = n > target ? n - target : target - n;
        if (gap < best_gap)
        {
            best_gap = gap;
            best = std::move(z0);
        }
        if (n > target)
        {
            break;
        }
    }
    return best;
}

// Runs simulate + delta_energy over `edits` kPasses times; returns the sum of ΔE (kept so the
// work cannot be optimised away).
double run_passes(const EnergyState& state, const ZomeMesh& mesh, const std::vector<const LocalChange*>& edits,
                  int passes)
{
    double sum = 0.0;
    for (int p = 0; p < passes; ++p)
    {
        for (const LocalChange* c : edits)
        {
            sum += state.delta_energy(state.simulate(mesh, *c));
        }
    }
    return sum;
}

// ΔE evaluations per second per thread, median over kRuns, with `threads` threads at once.
double per_thread_rate(int threads, const EnergyState& state, const ZomeMesh& mesh,
                       const std::vector<const LocalChange*>& edits)
{
    std::vector<double> sums(static_cast<size_t>(threads), 0.0);
    const double seconds = bench::median_seconds(kRuns, [&] {
        std::vector<std::thread> pool;
        for (int t = 0; t < threads; ++t)
        {
            pool.emplace_back([&, t] { sums[static_cast<size_t>(t)] = run_passes(state, mesh, edits, kPasses); });
        }
        for (std::thread& th : pool)
        {
            th.join();
        }
    });
    return static_cast<double>(edits.size()) * kPasses / seconds;
}

} // namespace

static int run_bench(int argc, char** argv)
{
    const std::string name = argc > 1 ? argv[1] : "bunny.obj";
    const size_t target = argc > 2 ? static_cast<size_t>(std::atol(argv[2])) : 400;
    const TriangleMesh surface = load_surface(std::string(ZOME_SHARED_DIR) + "/data/meshes/" + name);
    const SurfaceProjector projector(surface);
    const InsideTest inside(projector);
    const InitialModel z0 = z0_near(surface, inside, target);
    // Z0 is all quads; a few hundred random edits give the mix of triangles, quads and valences
    // that annealing works on (and proposals of every kind).
    ZomeMesh mesh = from_model(z0.model);
    test::EditRng rng(2024);
    for (size_t applied = 0; applied < mesh.n_vertices() / 2;)
    {
        if (std::optional<test::Edit> e = test::random_edit(mesh, rng))
        {
            e->apply(mesh);
            ++applied;
        }
    }
    mesh.garbage_collection();

    const ProjectionCacheOptions cache_options; // the defaults, as the annealer will use them
    const SurfaceContext context(projector, z0.model.transform, cache_options);
    EnergyOptions options;
    options.target_nodes = mesh.n_vertices();
    const EnergyState state(mesh, context, options);

    // Proposals on the unchanged mesh (simulate never edits it).
    std::vector<test::Edit> edits;
    while (edits.size() < kProposals)
    {
        if (std::optional<test::Edit> e = test::random_edit(mesh, rng))
        {
            edits.push_back(std::move(*e));
        }
    }
    std::vector<const LocalChange*> all;
    std::map<std::string, std::vector<const LocalChange*>> by_kind;
    double removed = 0.0, added = 0.0;
    for (const test::Edit& e : edits)
    {
        all.push_back(&e.change);
        by_kind[e.kind].push_back(&e.change);
        const LocalChange& c = e.change;
        removed += static_cast<double>(c.removed_nodes().size() + c.removed_struts().size() + c.removed_faces().size());
        added += static_cast<double>(c.added_nodes().size() + c.added_struts().size() + c.added_faces().size());
    }

    // A second context whose cache starts empty: its one pass sees every sample's first occurrence.
    SurfaceContext cold_context(projector, z0.model.transform, cache_options);
    const EnergyState cold_state(mesh, cold_context, options);
    cold_context.clear_cache();
    const double cold_s = bench::median_seconds(1, [&] { run_passes(cold_state, mesh, all, 1); });
    const ProjectionCacheStats cold_stats = cold_context.cache_stats();

    run_passes(state, mesh, all, 1); // warm the cache
    const double rate1 = per_thread_rate(1, state, mesh, all);
    const double rate2 = per_thread_rate(2, state, mesh, all);
    nlohmann::json kinds = nlohmann::json::object();
    for (const auto& [kind, list] : by_kind)
    {
        kinds[kind] = {{"proposals", list.size()}, {"delta_e_per_s", per_thread_rate(1, state, mesh, list)}};
    }
    const double full_s = bench::median_seconds(kRuns, [&] { evaluate_energy(mesh, context, options); });
    const EnergyTerms terms = state.terms();

    const nlohmann::json out = {
        {"bench", "energy"},
        {"platform", bench::platform()},
        {"mesh", name},
        {"resolution", z0.report.layout.resolution},
        {"nodes", mesh.n_vertices()},
        {"struts", mesh.n_edges()},
        {"faces", mesh.n_faces()},
        {"energy",
         {{"total", terms.total},
          {"distance", terms.distance},
          {"orientation", terms.orientation},
          {"fairing", terms.fairing},
          {"complexity", terms.complexity}}},
        {"proposals", all.size()},
        {"mean_removed_elements", removed / static_cast<double>(all.size())},
        {"mean_added_elements", added / static_cast<double>(all.size())},
        {"cold_cache_delta_e_per_s", static_cast<double>(all.size()) / cold_s},
        {"cold_cache_misses_per_proposal", static_cast<double>(cold_stats.misses) / static_cast<double>(all.size())},
        {"delta_e_per_s_1_thread", rate1},
        {"delta_e_per_s_per_thread_2_threads", rate2},
        {"delta_e_per_s_total_2_threads", 2.0 * rate2},
        {"by_kind_1_thread", kinds},
        {"full_evaluation_ms_median", full_s * 1e3},
        {"hardware_threads", std::thread::hardware_concurrency()},
        {"peak_memory_mib", bench::peak_memory_mib()},
    };
    std::cout << out.dump() << std::endl;
    return 0;
}

int main(int argc, char** argv) { return zomeify::bench::guarded_main(argc, argv, run_bench); }
