// Z0 (issue 4): voxelization + topology-safe cleanup + extraction for one shared mesh at one
// resolution (default rockerarm at 40 cells along the longest side), median of 5 runs, with each
// stage's median as well. The inside test's BVH is built once beforehand and reported apart:
// the pipeline shares it with the annealer's projections. Prints one JSON object.
// Usage: bench_voxel [mesh.obj [resolution]]   (mesh name relative to the shared meshes folder)
#include <cstdlib>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/base/stopwatch.h"
#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/surface/prepare.h"
#include "core/voxel/extract.h"
#include "core/voxel/initial_model.h"
#include "core/voxel/repair.h"
#include "core/voxel/voxelize.h"
#include "tests/bench/bench_util.h"

using namespace zomeify;

static int run_bench(int argc, char** argv)
{
    constexpr int kRuns = 5;
    const std::string mesh_name = argc > 1 ? argv[1] : "rockerarm.obj";
    const int resolution = argc > 2 ? std::atoi(argv[2]) : 40;
    const TriangleMesh mesh = load_surface(std::string(ZOME_SHARED_DIR) + "/data/meshes/" + mesh_name);

    Stopwatch setup_clock;
    const SurfaceProjector projector(mesh);
    const InsideTest inside(projector);
    const double setup = setup_clock.seconds();
    const InsidePredicate is_inside = [&](const Vec3& p) { return inside.is_inside(p); };

    InitialModelOptions options;
    options.resolution = resolution;
    options.surface_probe = probe_of(projector);
    InitialModel z0;
    const double total = bench::median_seconds(kRuns, [&] { z0 = build_initial_model(mesh, is_inside, options); });

    // The stages one by one, on the grid the pipeline used.
    const GridSpec spec = z0.report.grid;
    VoxelGrid grid;
    const double t_voxelize = bench::median_seconds(kRuns, [&] { grid = voxelize(mesh, spec, is_inside); });
    VoxelGrid cleaned;
    const double t_repair = bench::median_seconds(kRuns, [&] {
        cleaned = grid;
        repair_manifold(cleaned);
    });
    const double t_extract = bench::median_seconds(kRuns, [&] { extract_boundary(cleaned); });

    nlohmann::json j;
    j["benchmark"] = "bench_voxel";
    j["platform"] = bench::platform();
    j["mesh"] = mesh_name;
    j["triangles"] = mesh.triangles.size();
    j["resolution"] = resolution;
    j["grid"] = spec.dims;
    j["voxels"] = z0.report.voxels;
    j["nodes"] = z0.model.nodes.size();
    j["struts"] = z0.model.struts.size();
    j["genus"] = z0.report.topology.genus;
    j["valid"] = z0.report.valid;
    j["attempts"] = z0.report.attempts;
    j["runs"] = kRuns;
    j["inside_test_setup_s"] = setup;
    j["z0_median_s"] = total;
    j["voxelize_median_s"] = t_voxelize;
    j["cleanup_median_s"] = t_repair;
    j["extract_median_s"] = t_extract;
    j["inside_queries"] = z0.report.voxelize.inside_queries;
    j["box_tests"] = z0.report.voxelize.box_tests;
    j["peak_memory_mib"] = bench::peak_memory_mib();
    std::cout << j.dump() << "\n";
    return 0;
}

int main(int argc, char** argv) { return zomeify::bench::guarded_main(argc, argv, run_bench); }
