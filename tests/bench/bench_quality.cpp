// Time-to-quality: energy against wall time while annealing bunny, fertility and rockerarm from their
// Z0 (at a resolution that keeps each shape's genus), N_target = the Z0's node count. Prints one JSON
// object with one curve per mesh ([seconds, energy] points) for tests/bench/plot_curves.py.
// Usage: bench_quality [--seconds S] [--threads T] [mesh.obj ...]   (defaults: 20 s, 2 threads)
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/anneal/engine/annealer.h"
#include "core/geom/inside.h"
#include "core/surface/prepare.h"
#include "core/voxel/initial_model.h"
#include "tests/bench/bench_util.h"

using namespace zomeify;

namespace {

// Resolutions at which Z0 keeps the genus of the shape (README: the Z0 outcome table).
const std::map<std::string, int> resolutions = {{"bunny.obj", 8}, {"fertility.obj", 16}, {"rockerarm.obj", 12}};

nlohmann::json curve(const std::string& name, double seconds, int threads)
{
    const TriangleMesh surface = load_surface(std::string(ZOME_SHARED_DIR) + "/data/meshes/" + name);
    const SurfaceProjector projector(surface);
    const InsideTest inside(projector);
    InitialModelOptions initial;
    const auto it = resolutions.find(name);
    initial.resolution = it == resolutions.end() ? 12 : it->second;
    initial.surface_probe = probe_of(projector);
    const ZomeModel z0 = build_initial_model(
                             surface, [&](const Vec3& p) { return inside.is_inside(p); }, initial)
                             .model;

    const SurfaceContext context(projector, z0.transform);
    AnnealOptions options;
    options.seconds = seconds;
    options.threads = threads;
    options.seed = 1;
    options.progress_interval = seconds / 60.0;
    Annealer annealer(z0, context, options);
    // The curve starts at the Z0's energy; the first progress sample comes one interval later.
    nlohmann::json points = nlohmann::json::array({nlohmann::json::array({0.0, annealer.start_energy().total})});
    const AnnealResult result = annealer.run([&](const AnnealProgress& p) {
        points.push_back({p.elapsed_seconds, p.energy.total});
    });
    return {
        {"mesh", name},
        {"resolution", initial.resolution},
        {"threads", result.stats.threads},
        {"z0_nodes", z0.nodes.size()},
        {"nodes_end", result.model.nodes.size()},
        {"energy_start", result.start.total},
        {"energy_end", result.end.total},
        {"energy_best", result.best.total},
        {"proposals", result.stats.proposals},
        {"commits", result.stats.commits},
        {"points", points},
    };
}

} // namespace

static int run_bench(int argc, char** argv)
{
    double seconds = 20.0;
    int threads = 2;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--seconds" && i + 1 < argc)
            seconds = std::atof(argv[++i]);
        else if (arg == "--threads" && i + 1 < argc)
            threads = std::atoi(argv[++i]);
        else
            names.push_back(arg);
    }
    if (names.empty())
        names = {"bunny.obj", "fertility.obj", "rockerarm.obj"};
    nlohmann::json curves = nlohmann::json::array();
    for (const std::string& name : names)
        curves.push_back(curve(name, seconds > 0 ? seconds : 20.0, threads));
    const nlohmann::json out = {
        {"bench", "quality"},
        {"platform", bench::platform()},
        {"seconds_per_mesh", seconds},
        {"curves", curves},
        {"peak_memory_mib", bench::peak_memory_mib()},
    };
    std::cout << out.dump() << std::endl;
    return 0;
}

int main(int argc, char** argv) { return zomeify::bench::guarded_main(argc, argv, run_bench); }
