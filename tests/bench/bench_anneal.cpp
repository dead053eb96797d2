// The annealer's throughput and time-to-quality on the bunny at about 400 nodes (Z0 at 8 cells,
// 330 nodes, N_target 392 as in the paper's bunny). Prints one JSON object.
//
//   bench_anneal [throughput] [SECONDS]   proposals/s and commits/s at 1, 2, 4, 8 threads, each a
//                                         SECONDS-long run (default 5); wall and process CPU time
//   bench_anneal quality [S1 S2 THREADS]  the energy reached in S1 and in S2 seconds (default 30
//                                         and 300, 2 threads), with energy-vs-time points
//                                         (every 0.5 s) to plot
//   bench_anneal compare [SECONDS ROUNDS] proposals/s on one thread with the defaults against the
//                                         paper's energy without the clearance rule (what the
//                                         annealer did before E_surface and clearances), ROUNDS
//                                         alternating pairs of SECONDS-long runs (default 5 s, 5):
//                                         the ratio of each pair and their median
//   bench_anneal seeding [PROPOSALS N]    the final energy with seeds from sweeping slabs and with
//                                         seeds drawn uniformly (the paper's way), one thread, a
//                                         budget of PROPOSALS (default 2e7), seeds 1..N (default 3):
//                                         deterministic runs, so the load of the machine does not
//                                         matter
//
// CPU time is reported beside wall time because the machine may be shared: proposals per CPU
// second do not drop when another process takes a core, proposals per wall second do.
#include <algorithm>
#include <ctime>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/anneal/engine/annealer.h"
#include "core/geom/inside.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "core/surface/prepare.h"
#include "core/voxel/initial_model.h"
#include "tests/bench/bench_util.h"

using namespace zomeify;

namespace {

constexpr int kResolution = 8;
constexpr size_t kTargetNodes = 392;

struct Scene
{
    TriangleMesh surface;
    std::unique_ptr<SurfaceProjector> projector;
    ZomeModel z0;
};

Scene bunny()
{
    Scene s;
    s.surface = load_surface(std::string(ZOME_SHARED_DIR) + "/data/meshes/bunny.obj");
    s.projector = std::make_unique<SurfaceProjector>(s.surface);
    const InsideTest inside(*s.projector);
    InitialModelOptions o;
    o.resolution = kResolution;
    o.surface_probe = probe_of(*s.projector);
    o.target_genus = 0;
    s.z0 = build_initial_model(
               s.surface, [&](const Vec3& p) { return inside.is_inside(p); }, o)
               .model;
    return s;
}

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

nlohmann::json terms(const EnergyTerms& t)
{
    return {{"total", t.total},     {"distance", t.distance},     {"orientation", t.orientation},
            {"fairing", t.fairing}, {"complexity", t.complexity}, {"nodes", t.sums.nodes}};
}

nlohmann::json throughput(const Scene& s, double seconds)
{
    nlohmann::json runs = nlohmann::json::array();
    for (int threads : {1, 2, 4, 8})
    {
        // A fresh context per run: every run starts with a cold projection cache.
        const SurfaceContext context(*s.projector, s.z0.transform);
        AnnealOptions o;
        o.threads = threads;
        o.seconds = seconds;
        o.seed = 1;
        o.target_nodes = kTargetNodes;
        Annealer annealer(s.z0, context, o);
        const double cpu0 = cpu_seconds();
        const AnnealResult r = annealer.run();
        const double cpu = cpu_seconds() - cpu0;
        const AnnealStats& st = r.stats;
        runs.push_back(
            {{"threads", threads},
             {"wall_seconds", st.wall_seconds},
             {"cpu_seconds", cpu},
             {"proposals", st.proposals},
             {"commits", st.commits},
             {"proposals_per_second", st.proposals_per_second},
             {"commits_per_second", st.commits_per_second},
             {"proposals_per_cpu_second", cpu > 0 ? static_cast<double>(st.proposals) / cpu : 0.0},
             {"busy_seeds", st.busy_seeds},
             {"dead_seeds", st.dead_seeds},
             {"lost_races", st.lost_races},
             {"pauses", st.garbage_collections},
             {"redecisions", st.redecisions},
             {"commit_hold_seconds", st.commit_hold_seconds},
             {"commit_wait_seconds", st.commit_wait_seconds},
             // The serial fraction: the commit section's share of the threads' time.
             {"serial_fraction", st.wall_seconds > 0 ? st.commit_hold_seconds / (threads * st.wall_seconds) : 0.0},
             {"energy_start", r.start.total},
             {"energy_end", r.end.total},
             {"nodes_end", r.model.nodes.size()},
             {"energy_consistent", st.energy_consistent}});
    }
    const double one = runs[0]["proposals_per_second"].get<double>();
    for (auto& run : runs)
        run["speedup_vs_1_thread"] = one > 0 ? run["proposals_per_second"].get<double>() / one : 0.0;
    return runs;
}

// One-thread proposals per CPU second of a SECONDS-long run with `o`.
double rate(const Scene& s, AnnealOptions o, double seconds)
{
    const SurfaceContext context(*s.projector, s.z0.transform);
    o.threads = 1;
    o.seconds = seconds;
    o.seed = 1;
    o.target_nodes = kTargetNodes;
    Annealer annealer(s.z0, context, o);
    const double cpu0 = cpu_seconds();
    const AnnealResult r = annealer.run();
    const double cpu = cpu_seconds() - cpu0;
    return cpu > 0 ? static_cast<double>(r.stats.proposals) / cpu : 0.0;
}

nlohmann::json compare(const Scene& s, double seconds, int rounds)
{
    AnnealOptions before;
    before.energy = paper_energy();
    before.clearance = false;
    nlohmann::json pairs = nlohmann::json::array();
    std::vector<double> ratios;
    for (int i = 0; i < rounds; ++i)
    {
        // Alternate which goes first, so a drift of the host's speed falls on both alike.
        const bool defaults_first = i % 2 == 1;
        double now = 0.0, paper = 0.0;
        if (defaults_first)
            now = rate(s, AnnealOptions{}, seconds);
        paper = rate(s, before, seconds);
        if (!defaults_first)
            now = rate(s, AnnealOptions{}, seconds);
        ratios.push_back(paper > 0 ? now / paper : 0.0);
        pairs.push_back({{"defaults_per_cpu_second", now}, {"paper_per_cpu_second", paper}, {"ratio", ratios.back()}});
    }
    std::sort(ratios.begin(), ratios.end());
    return {{"pairs", pairs},
            {"median_ratio", ratios[ratios.size() / 2]},
            {"min_ratio", ratios.front()},
            {"max_ratio", ratios.back()}};
}

nlohmann::json quality_run(const Scene& s, double seconds, int threads)
{
    const SurfaceContext context(*s.projector, s.z0.transform);
    AnnealOptions o;
    o.threads = threads;
    o.seconds = seconds;
    o.seed = 1;
    o.target_nodes = kTargetNodes;
    o.progress_interval = 0.5;
    Annealer annealer(s.z0, context, o);
    nlohmann::json curve = nlohmann::json::array();
    const AnnealResult r = annealer.run([&](const AnnealProgress& p) {
        curve.push_back({p.elapsed_seconds, p.energy.total, p.temperature, p.nodes});
    });
    const ZomeMesh mesh = from_model(r.model);
    const ValidationReport check = validate(mesh);
    return {{"seconds", seconds},
            {"threads", r.stats.threads},
            {"proposals", r.stats.proposals},
            {"commits", r.stats.commits},
            {"energy_start", terms(r.start)},
            {"energy_end", terms(r.end)},
            {"energy_best", r.best.total},
            {"valid", check.ok()},
            {"genus", check.genus},
            {"curve_columns", {"seconds", "energy", "temperature", "nodes"}},
            {"curve", curve}};
}

nlohmann::json seeding(const Scene& s, uint64_t proposals, int seeds)
{
    nlohmann::json out;
    for (const bool sweep : {true, false})
    {
        nlohmann::json energies = nlohmann::json::array();
        std::vector<double> values;
        for (int seed = 1; seed <= seeds; ++seed)
        {
            const SurfaceContext context(*s.projector, s.z0.transform);
            AnnealOptions o;
            o.threads = 1;
            o.max_proposals = proposals;
            o.seed = static_cast<uint64_t>(seed);
            o.target_nodes = kTargetNodes;
            o.sweep_slabs = sweep;
            Annealer annealer(s.z0, context, o);
            const AnnealResult r = annealer.run();
            energies.push_back(r.end.total);
            values.push_back(r.end.total);
        }
        std::sort(values.begin(), values.end());
        out[sweep ? "sweeping_slabs" : "uniform"] = {{"energies", energies}, {"median", values[values.size() / 2]}};
    }
    out["proposals"] = proposals;
    return out;
}

} // namespace

static int run_bench(int argc, char** argv)
{
    const std::string mode = argc > 1 ? argv[1] : "throughput";
    const Scene s = bunny();
    nlohmann::json j;
    j["benchmark"] = "anneal";
    j["platform"] = bench::platform();
    j["mesh"] = "bunny.obj";
    j["resolution"] = kResolution;
    j["z0_nodes"] = s.z0.nodes.size();
    j["target_nodes"] = kTargetNodes;
    if (mode == "quality")
    {
        const double s1 = argc > 2 ? bench::positive_argument(argv[2], "S1") : 30.0;
        const double s2 = argc > 3 ? bench::positive_argument(argv[3], "S2") : 300.0;
        const int threads = argc > 4 ? static_cast<int>(bench::positive_argument(argv[4], "THREADS")) : 2;
        j["mode"] = "quality";
        j["short"] = quality_run(s, s1, threads);
        j["long"] = quality_run(s, s2, threads);
        const double e1 = j["short"]["energy_end"]["total"].get<double>();
        const double e2 = j["long"]["energy_end"]["total"].get<double>();
        j["short_over_long"] = e2 > 0 ? e1 / e2 : 0.0;
    }
    else if (mode == "compare")
    {
        const double seconds = argc > 2 ? bench::positive_argument(argv[2], "SECONDS") : 5.0;
        const int rounds = argc > 3 ? static_cast<int>(bench::positive_argument(argv[3], "ROUNDS")) : 5;
        j["mode"] = "compare";
        j["seconds_per_run"] = seconds;
        j["compare"] = compare(s, seconds, std::max(rounds, 1));
    }
    else if (mode == "seeding")
    {
        const double proposals = argc > 2 ? bench::positive_argument(argv[2], "PROPOSALS") : 2e7;
        const int seeds = argc > 3 ? static_cast<int>(bench::positive_argument(argv[3], "N")) : 3;
        j["mode"] = "seeding";
        j["seeding"] = seeding(s, static_cast<uint64_t>(std::max(proposals, 1.0)), std::max(seeds, 1));
    }
    else
    {
        // `bench_anneal throughput [SECONDS]` or `bench_anneal SECONDS`; anything else is an error.
        const double seconds =
            mode == "throughput"
                ? (argc > 2 ? bench::positive_argument(argv[2], "SECONDS") : 5.0)
                : bench::positive_argument(argv[1], "the mode (throughput, compare, quality, seeding) or SECONDS");
        j["mode"] = "throughput";
        j["seconds_per_run"] = seconds;
        j["runs"] = throughput(s, seconds > 0 ? seconds : 5.0);
    }
    j["peak_memory_mib"] = bench::peak_memory_mib();
    std::cout << j.dump(2) << "\n";
    return 0;
}

int main(int argc, char** argv) { return zomeify::bench::guarded_main(argc, argv, run_bench); }
