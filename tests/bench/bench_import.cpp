// Import of every shared mesh: read the file (parse only), diagnose, and prepare (repair into the closed
// triangle mesh the pipeline uses); medians of repeated runs, plus the process's peak memory after
// each mesh. Then a scan-sized mesh from the wild made here: a torus of 1,000,000 triangles with six
// holes of 3 to 300 edges (issue 36), diagnosed and repaired. Prints one JSON object.
// Usage: bench_import [--runs N] [--no-holed] [mesh.obj ...]   (names relative to the shared meshes folder;
// all by default)
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <numbers>
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

// Median times of diagnose and prepare_surface on one soup, with the report and the result's size.
struct Prepared
{
    SurfaceReport report;
    size_t triangles = 0;
    double diagnose_s = 0.0, prepare_s = 0.0;
};

Prepared time_prepare(const PolygonSoup& soup, int runs)
{
    Prepared p;
    p.diagnose_s = bench::median_seconds(runs, [&] { p.report = diagnose(soup); });
    p.prepare_s = bench::median_seconds(runs, [&] { p.triangles = prepare_surface(soup).mesh.triangles.size(); });
    return p;
}

nlohmann::json bench_mesh(const std::string& name, int runs)
{
    const std::string path = meshes_dir + name;
    PolygonSoup soup;
    const double read_s = bench::median_seconds(runs, [&] { soup = read_mesh_file(path); });
    const Prepared p = time_prepare(soup, runs);
    const SurfaceReport& report = p.report;
    const size_t triangles = p.triangles;
    const double diagnose_s = p.diagnose_s, prepare_s = p.prepare_s;
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

// A torus of nu x nv quads split into 2 nu nv triangles, less six rectangular patches of quads:
// holes with rims of 3 (one triangle), 4, 12, 40, 100 and 300 edges.
PolygonSoup holed_torus(int nu, int nv)
{
    PolygonSoup s;
    s.positions.reserve(static_cast<size_t>(nu) * nv);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j)
        {
            const double a = 2 * std::numbers::pi * i / nu, b = 2 * std::numbers::pi * j / nv;
            s.positions.push_back(
                Vec3((2 + 0.8 * std::cos(b)) * std::cos(a), 0.8 * std::sin(b), (2 + 0.8 * std::cos(b)) * std::sin(a)));
        }
    const auto at = [&](int i, int j) { return static_cast<uint32_t>((i % nu) * nv + (j % nv)); };
    struct Patch
    {
        int i, j, size; // size x size quads from (i, j); 0: one triangle
    };
    const Patch patches[] = {{10, 10, 0}, {100, 20, 1}, {200, 30, 3}, {300, 40, 10}, {450, 50, 25}, {700, 100, 75}};
    const auto in_patch = [&](int i, int j) {
        for (const Patch& p : patches)
            if (p.size > 0 && i >= p.i && i < p.i + p.size && j >= p.j && j < p.j + p.size)
                return true;
        return false;
    };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j)
        {
            if (in_patch(i, j))
                continue;
            s.polygons.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            if (!(i == patches[0].i && j == patches[0].j))
                s.polygons.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return s;
}

nlohmann::json bench_holed_torus(int runs)
{
    const PolygonSoup soup = holed_torus(1000, 500);
    const Prepared p = time_prepare(soup, runs);
    const SurfaceReport& report = p.report;
    const size_t triangles = p.triangles;
    const double diagnose_s = p.diagnose_s, prepare_s = p.prepare_s;
    return {
        {"mesh", "holed torus (generated)"},
        {"vertices", soup.positions.size()},
        {"input_faces", soup.polygons.size()},
        {"holes", report.input_holes},
        {"holes_filled", report.filled_holes},
        {"genus", report.genus},
        {"triangles", triangles},
        {"diagnose_ms_median", diagnose_s * 1e3},
        {"prepare_ms_median", prepare_s * 1e3},
        {"ok", report.ok()},
        {"peak_memory_mib_after", bench::peak_memory_mib()},
    };
}

} // namespace

static int run_bench(int argc, char** argv)
{
    int runs = 5;
    bool holed = true;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else if (arg == "--no-holed")
            holed = false;
        else
            names.push_back(arg);
    }
    if (names.empty())
        names = all_shared_meshes();
    nlohmann::json meshes = nlohmann::json::array();
    for (const std::string& name : names)
        meshes.push_back(bench_mesh(name, runs));
    if (holed)
        meshes.push_back(bench_holed_torus(std::min(runs, 3)));
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
