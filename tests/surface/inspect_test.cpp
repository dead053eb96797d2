// `zomeify inspect` (design.md §5): the report's text forms, and the CLI itself on the shared
// meshes (issue 3 acceptance: `inspect --json` gives the README's V, F, closedness and genus).
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/surface/prepare.h"
#include "core/surface/report_text.h"
#include "tests/support/paths.h"
#include "tests/surface/surface_fixtures.h"

#ifndef __EMSCRIPTEN__
#include <sys/wait.h>
#endif

namespace zomeify::surface_test {
namespace {

TEST(InspectReport, TableAndJsonOfARepairedCube)
{
    const SurfaceReport r = diagnose(reversed(cube_quads()));
    const std::string table = surface_report_table(r, "cube.obj");
    EXPECT_NE(table.find("vertices        8\n"), std::string::npos) << table;
    EXPECT_NE(table.find("faces           12 triangles\n"), std::string::npos) << table;
    EXPECT_NE(table.find("closed          yes\n"), std::string::npos) << table;
    EXPECT_NE(table.find("genus           0\n"), std::string::npos) << table;
    EXPECT_NE(table.find("repaired        triangulated 6 polygons\n"), std::string::npos) << table;
    EXPECT_NE(table.find("                flipped 12 faces"), std::string::npos) << table;
    EXPECT_NE(table.find("problems        none\n"), std::string::npos) << table;

    const auto j = nlohmann::json::parse(surface_report_json(r, "cube.obj"));
    EXPECT_EQ(j["file"], "cube.obj");
    EXPECT_EQ(j["ok"], true);
    EXPECT_EQ(j["vertices"], 8);
    EXPECT_EQ(j["faces"], 12);
    EXPECT_EQ(j["closed"], true);
    EXPECT_EQ(j["genus"], 0);
    EXPECT_EQ(j["repairs"]["flipped_faces"], 12);
    EXPECT_EQ(j["repairs"]["triangulated_polygons"], 6);
    EXPECT_EQ(j["bbox"]["max"][2], 1.0);
    EXPECT_NEAR(j["bbox"]["diagonal"].get<double>(), std::sqrt(3.0), 1e-12);
}

TEST(InspectReport, ProblemsInTable)
{
    PolygonSoup quad;
    quad.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    quad.polygons = {{0, 1, 2, 3}};
    const std::string table = surface_report_table(diagnose(quad), "quad.obj");
    EXPECT_NE(table.find("closed          no (1 hole, 4 boundary edges)"), std::string::npos) << table;
    EXPECT_NE(table.find("problems        mesh is an open sheet"), std::string::npos) << table;
}

TEST(InspectReport, RepairsInTable)
{
    PolygonSoup box = cube_quads();
    box.polygons.pop_back();
    const std::string table = surface_report_table(diagnose(box), "box.obj");
    EXPECT_NE(table.find("closed          yes\n"), std::string::npos) << table;
    EXPECT_NE(table.find("closed 1 small hole (4 edges)"), std::string::npos) << table;
    EXPECT_NE(table.find("problems        none"), std::string::npos) << table;
}

#ifndef __EMSCRIPTEN__

struct CliResult
{
    int status = -1;
    std::string out;
    std::string err;
};

// Runs the real CLI binary; stderr goes through a scratch file.
CliResult run_cli(const std::string& arguments)
{
    const std::string err_path = test::temp_path("inspect_stderr.txt");
    const std::string command = std::string("'") + ZOME_CLI_PATH + "' " + arguments + " 2>'" + err_path + "'";
    CliResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe)
        return result;
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0)
        result.out.append(buffer, n);
    const int status = pclose(pipe);
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream err(err_path);
    result.err.assign(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
    return result;
}

TEST(InspectCli, JsonMatchesReadmeForAllSharedMeshes)
{
    ZOME_REQUIRE_SHARED();
    struct Expected
    {
        const char* file;
        int genus, vertices, faces;
    };
    const Expected meshes[] = {
        {"fertility.obj", 4, 4494, 9000}, {"rockerarm.obj", 1, 10044, 20088}, {"bunny.obj", 0, 3301, 6598},
        {"elk.obj", 1, 5194, 10388},      {"torus.obj", 1, 2304, 4608},       {"sphere.obj", 0, 642, 1280},
        {"cube.obj", 0, 26, 48},          {"eight.obj", 2, 766, 1536},        {"3holes.obj", 3, 3596, 7200},
        {"scorpion.obj", 0, 6315, 12626},
    };
    for (const Expected& m : meshes)
    {
        SCOPED_TRACE(m.file);
        const CliResult r = run_cli("inspect '" + test::shared_path(std::string("data/meshes/") + m.file) + "' --json");
        ASSERT_EQ(r.status, 0) << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j["vertices"], m.vertices);
        EXPECT_EQ(j["faces"], m.faces);
        EXPECT_EQ(j["closed"], true);
        EXPECT_EQ(j["manifold"], true);
        EXPECT_EQ(j["components"], 1);
        EXPECT_EQ(j["genus"], m.genus);
        EXPECT_TRUE(j["repaired"].empty());
        EXPECT_TRUE(r.err.empty());
    }
}

TEST(InspectCli, AutomaticGridIsTheOneRunTakes)
{
    // issue 37: `inspect --json`, `inspect` and `run --initial-only` give one grid and one sentence.
    ZOME_REQUIRE_SHARED();
    for (const char* file : {"torus.obj", "fertility.obj"})
    {
        SCOPED_TRACE(file);
        const std::string mesh = "'" + test::shared_path(std::string("data/meshes/") + file) + "'";
        const CliResult inspect = run_cli("inspect " + mesh + " --json");
        ASSERT_EQ(inspect.status, 0) << inspect.err;
        const auto a = nlohmann::json::parse(inspect.out)["automatic_resolution"];
        const std::string message = a["message"].get<std::string>();
        EXPECT_EQ(message.rfind(std::to_string(a["resolution"].get<int>()) + " cells (", 0), 0u) << message;
        EXPECT_TRUE(a["genus_kept"].get<bool>());
        EXPECT_GT(a["target_nodes"].get<int>(), a["balls"].get<int>());
        const CliResult table = run_cli("inspect " + mesh);
        EXPECT_NE(table.out.find("automatic grid  " + message + "\n"), std::string::npos) << table.out;
        const CliResult run =
            run_cli("run " + mesh + " --initial-only -o '" + test::temp_path("auto_z0.zome.json") + "'");
        ASSERT_EQ(run.status, 0) << run.err;
        EXPECT_NE(run.out.find("Resolution chosen automatically: " + message + "."), std::string::npos) << run.out;
    }
}

TEST(InspectCli, MirrorPlaneOfASymmetricAndALopsidedShape)
{
    // issue 41: the best mirror plane and how far the mirror image lies, in mm at the automatic size.
    ZOME_REQUIRE_SHARED();
    const CliResult torus = run_cli("inspect '" + test::shared_path("data/meshes/torus.obj") + "' --json");
    ASSERT_EQ(torus.status, 0) << torus.err;
    const auto t = nlohmann::json::parse(torus.out)["mirror_plane"];
    EXPECT_LT(t["rms_mm"].get<double>(), 0.5);
    EXPECT_LT(t["max_mm"].get<double>(), 1.0);
    EXPECT_NEAR(t["at_size_cm"].get<double>(),
                nlohmann::json::parse(torus.out)["automatic_resolution"]["size_cm"].get<double>(), 1e-9);
    const CliResult bunny = run_cli("inspect '" + test::shared_path("data/meshes/bunny.obj") + "'");
    ASSERT_EQ(bunny.status, 0) << bunny.err;
    const size_t at = bunny.out.find("mirror plane    normal (");
    ASSERT_NE(at, std::string::npos) << bunny.out;
    const CliResult bunny_json = run_cli("inspect '" + test::shared_path("data/meshes/bunny.obj") + "' --json");
    EXPECT_GT(nlohmann::json::parse(bunny_json.out)["mirror_plane"]["rms_mm"].get<double>(), 10.0);
}

TEST(InspectCli, Table)
{
    ZOME_REQUIRE_SHARED();
    const CliResult r = run_cli("inspect '" + test::shared_path("data/meshes/eight.obj") + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("genus           2\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("vertices        766\n"), std::string::npos) << r.out;
}

TEST(InspectCli, OpenSheetReportsAndFails)
{
    PolygonSoup quad;
    quad.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    quad.polygons = {{0, 1, 2, 3}};
    const std::string path = test::temp_path("quad.obj");
    std::ofstream(path) << to_obj(quad);
    const CliResult r = run_cli("inspect '" + path + "' --json");
    EXPECT_EQ(r.status, 1);
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["ok"], false);
    EXPECT_EQ(j["holes"], 1);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("quad.obj: mesh is an open sheet, not a solid"), std::string::npos) << r.err;
}

TEST(InspectCli, OpenBoxIsRepairedAndListed)
{
    PolygonSoup box = cube_quads();
    box.polygons.pop_back();
    const std::string path = test::temp_path("open_box.obj");
    std::ofstream(path) << to_obj(box);
    const CliResult r = run_cli("inspect '" + path + "' --json");
    EXPECT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["ok"], true);
    EXPECT_EQ(j["holes"], 0);
    EXPECT_EQ(j["input_defects"]["holes"], 1);
    EXPECT_EQ(j["repairs"]["filled_holes"], 1);
    EXPECT_EQ(j["repaired"].back(), "closed 1 small hole (4 edges)");
}

TEST(InspectCli, UnreadableFileIsOneLineError)
{
    const std::string path = test::temp_path("garbage.stl");
    std::ofstream(path, std::ios::binary)
        << std::string("\x89PNG\r\n\x1a\n and more bytes that are not a mesh at all", 50);
    for (const std::string& args : {"inspect '" + path + "'", "inspect '" + test::temp_path("missing.ply") + "'",
                                    std::string("inspect"), "inspect '" + path + "' --xml"})
    {
        SCOPED_TRACE(args);
        const CliResult r = run_cli(args);
        EXPECT_EQ(r.status, 1);
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(r.err.rfind("zomeify: ", 0), 0u) << r.err;
    }
}

#endif

} // namespace
} // namespace zomeify::surface_test
