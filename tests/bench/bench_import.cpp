// Import of every shared mesh: read the file (parse only), diagnose, and prepare (repair into the closed
// triangle mesh the pipeline uses); medians of repeated runs, plus the process's peak memory after
// each mesh. Prints one JSON object.
// Usage: bench_import [--runs N] [mesh.obj ...]   (names relative to the shared meshes folder; all by default)
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "tests/bench/bench_util.h"

using namespace zomeify;

namespace {

const std::string meshes_dir = std::string(ZOME_SHARED_DIR) + "/data/meshes/";

std::vector<std::string> all_shared_meshes()
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(meshes_dir))
        if (is_mesh_file_name(entry.path().filename().string()))
            names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

nlohmann::json bench_mesh(const std::string& name, int runs)
{
    const std::string path = meshes_dir + name;
    PolygonSoup soup;
    const double read_s = bench::median_seconds(runs, [&] { soup = read_mesh_file(path); });
    SurfaceReport report;
    const double diagnose_s = bench::median_seconds(runs, [&] { report = diagnose(soup); });
    size_t triangles = 0;
    const double prepare_s =
        bench::median_seconds(runs, [&] { triangles = prepare_surface(soup).mesh.triangles.size(); });
    return {
        {"mesh", name},
        {"file_bytes", std::filesystem::file_size(path)},
        {"vertices", soup.positions.size()},
        {"input_faces", soup.polygons.size()},
        {"triangles", triangles},
        {"read_ms_median", read_s * 1e3},
        {"diagnose_ms_median", diagnose_s * 1e3},
        {"prepare_ms_median", prepare_s * 1e3},
        {"read_and_prepare_ms", (read_s + prepare_s) * 1e3},
        {"read_mb_per_s", static_cast<double>(std::filesystem::file_size(path)) / read_s / 1e6},
        {"ok", report.ok()},
        {"peak_memory_mib_after", bench::peak_memory_mib()},
    };
}

} // namespace

static int run_bench(int argc, char** argv)
{
    int runs = 5;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else
            names.push_back(arg);
    }
    if (names.empty())
        names = all_shared_meshes();
    nlohmann::json meshes = nlohmann::json::array();
    for (const std::string& name : names)
        meshes.push_back(bench_mesh(name, runs));
    const nlohmann::json out = {
        {"bench", "import"},
        {"platform", bench::platform()},
        {"runs", runs},
        {"meshes", meshes},
        {"peak_memory_mib", bench::peak_memory_mib()},
    };
    std::cout << out.dump() << std::endl;
    return 0;
}

int main(int argc, char** argv) { return zomeify::bench::guarded_main(argc, argv, run_bench); }
