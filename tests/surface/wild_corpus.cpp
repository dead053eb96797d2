#include "tests/surface/wild_corpus.h"

#include <cmath>
#include <numbers>

#include "tests/support/geom_fixtures.h"
#include "tests/surface/surface_fixtures.h"

namespace zomeify::surface_test {

namespace {

constexpr double pi = std::numbers::pi;

PolygonSoup soup_of(const TriangleMesh& m, const Vec3& offset = Vec3::Zero())
{
    PolygonSoup s;
    for (const Vec3& p : m.positions)
        s.positions.push_back(p + offset);
    for (const auto& t : m.triangles)
        s.polygons.push_back({t[0], t[1], t[2]});
    return s;
}

Vec3 centroid(const PolygonSoup& s, const std::vector<uint32_t>& polygon)
{
    Vec3 c = Vec3::Zero();
    for (const uint32_t v : polygon)
        c += s.positions[v];
    return c / static_cast<double>(polygon.size());
}

// A tetrahedron of edge about `size` at `at`, outward.
PolygonSoup tetrahedron(const Vec3& at, double size)
{
    PolygonSoup s;
    s.positions = {at, at + Vec3(size, 0, 0), at + Vec3(0, size, 0), at + Vec3(0, 0, size)};
    s.polygons = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return s;
}

// A tube of `radius` along z from 0 to `height`, without caps, outward.
PolygonSoup open_cylinder(double radius, double height, int segments, int rows)
{
    PolygonSoup s;
    for (int i = 0; i <= rows; ++i)
        for (int j = 0; j < segments; ++j)
        {
            const double a = 2 * pi * j / segments;
            s.positions.push_back(Vec3(radius * std::cos(a), radius * std::sin(a), height * i / rows));
        }
    const auto at = [&](int i, int j) { return static_cast<uint32_t>(i * segments + (j % segments)); };
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < segments; ++j)
            s.polygons.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
    return s;
}

// Rolling hills over a square: a terrain patch, open all round.
PolygonSoup terrain(int n)
{
    PolygonSoup s;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
        {
            const double x = double(i) / n, y = double(j) / n;
            s.positions.push_back(Vec3(x, y, 0.15 * std::sin(3 * x) * std::cos(4 * y)));
        }
    const auto at = [&](int i, int j) { return static_cast<uint32_t>(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            s.polygons.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    return s;
}

// A cube with one more triangle hanging from its edge x = 1, y = 1: that edge has three faces.
PolygonSoup cube_with_fin()
{
    PolygonSoup s = cube_quads();
    // cube_quads numbers its corners (x, y, z) = bits of the index: 3 is (1, 1, 0), 7 is (1, 1, 1).
    s.positions.push_back(Vec3(1.8, 1.8, 0.5));
    s.polygons.push_back({3, 7, 8});
    return s;
}

} // namespace

PolygonSoup punched(PolygonSoup soup, const Vec3& centre, double radius)
{
    std::vector<std::vector<uint32_t>> kept;
    for (auto& polygon : soup.polygons)
        if ((centroid(soup, polygon) - centre).norm() > radius)
            kept.push_back(std::move(polygon));
    soup.polygons = std::move(kept);
    return soup;
}

std::vector<WildMesh> wild_corpus()
{
    std::vector<WildMesh> corpus;
    const TriangleMesh sphere = test::make_uv_sphere(1.0, 24, 48);

    // A scan's pin-prick: one triangle missing.
    {
        PolygonSoup s = soup_of(sphere);
        s.polygons.erase(s.polygons.begin() + 600);
        corpus.push_back({"sphere, one 3-edge hole", s, 0, {"closed 1 small hole (3 edges)"}, ""});
    }
    // Seven holes of growing size round a torus.
    {
        PolygonSoup s = soup_of(test::make_torus(2.0, 0.8, 128, 64));
        s.polygons.erase(s.polygons.begin() + 5000);
        for (int k = 1; k < 7; ++k)
        {
            const double a = 2 * pi * k / 7;
            s = punched(s, Vec3(2.8 * std::cos(a), 0, 2.8 * std::sin(a)), 0.02 * k * k + 0.05);
        }
        corpus.push_back({"torus, 7 holes", s, 1, {"closed 7 holes ("}, ""});
    }
    // A bust's open base: one latitude ring of 500 edges (past the exact triangulation's limit).
    {
        PolygonSoup s = soup_of(test::make_uv_sphere(1.0, 16, 500));
        s = punched(s, Vec3(0, 0, -1), 0.45);
        corpus.push_back({"sphere, open base (500 edges)", s, 0, {"closed 1 hole (500 edges)"}, ""});
    }
    // A hole of about 300 edges on a fine sphere, triangulated exactly.
    {
        PolygonSoup s = soup_of(test::make_uv_sphere(1.0, 96, 192));
        s = punched(s, Vec3(1, 0, 0), 1.2);
        corpus.push_back({"sphere, one hole of about 300 edges", s, 0, {"closed 1 hole ("}, ""});
    }
    corpus.push_back({"two cubes touching at a corner",
                      merge(cube_quads(), cube_quads(Vec3(1, 1, 1))),
                      0,
                      {"separated 1 pinched vertex"},
                      ""});
    corpus.push_back({"two cubes sharing an edge",
                      merge(cube_quads(), cube_quads(Vec3(1, 1, 0))),
                      0,
                      {"separated the faces at 1 edge shared by more than two faces"},
                      ""});
    corpus.push_back({"cube with a fin on one edge",
                      cube_with_fin(),
                      0,
                      {"separated the faces at 1 edge", "dropped 1 open sheet beside the solid (1 face)"},
                      ""});
    {
        PolygonSoup s = soup_of(sphere);
        for (int k = 0; k < 5; ++k)
            s = merge(s, tetrahedron(Vec3(1.2 + 0.1 * k, 0.3 * k, 0.0), 0.004));
        corpus.push_back({"sphere with 5 specks", s, 0, {"dropped 5 specks (20 faces"}, ""});
    }
    {
        // A sphere with a hole and a pinched vertex where a small cone touches it: both repairs.
        PolygonSoup s = soup_of(sphere);
        s.polygons.erase(s.polygons.begin() + 300);
        PolygonSoup cone;
        cone.positions = {Vec3(0, 0, 1), Vec3(0.3, 0, 1.5), Vec3(-0.15, 0.26, 1.5), Vec3(-0.15, -0.26, 1.5),
                          Vec3(0, 0, 1.6)};
        cone.polygons = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 4, 2}, {2, 4, 3}, {3, 4, 1}};
        corpus.push_back({"sphere with a hole and a cone touching its pole",
                          merge(s, cone),
                          0,
                          {"closed 1 small hole (3 edges)", "separated 1 pinched vertex"},
                          ""});
    }
    corpus.push_back({"open cylinder (a tube, both ends open)",
                      open_cylinder(0.5, 2.0, 32, 8),
                      0,
                      {"closed 2 holes (32 edges each)"},
                      ""});
    {
        PolygonSoup s = cube_quads();
        s.polygons.erase(s.polygons.begin() + 1);
        corpus.push_back({"box without its lid", s, 0, {"closed 1 small hole (4 edges)"}, ""});
    }
    corpus.push_back({"two overlapping spheres",
                      merge(soup_of(sphere), soup_of(sphere, Vec3(1.2, 0, 0))),
                      0,
                      {"joined 2 overlapping parts into 1 solid"},
                      ""});
    // A mug made of two closed parts: a can, and a ring half pushed into it for a handle. The union
    // has the handle's hole: genus 1, though each part has genus 0 and 1 and they cross twice.
    {
        PolygonSoup can = open_cylinder(1.0, 2.0, 48, 12);
        const auto rim = static_cast<uint32_t>(can.positions.size());
        can.positions.push_back(Vec3(0, 0, 0));
        can.positions.push_back(Vec3(0, 0, 2));
        for (uint32_t j = 0; j < 48; ++j)
        {
            can.polygons.push_back({rim, (j + 1) % 48, j});
            can.polygons.push_back({rim + 1, 12 * 48 + j, 12 * 48 + (j + 1) % 48});
        }
        TriangleMesh ring = test::make_torus(0.7, 0.15, 64, 16); // round the y axis, in the xz plane
        for (Vec3& p : ring.positions)
            p += Vec3(1.0, 0.0, 1.0);
        corpus.push_back({"mug: a can and a ring pushed into it",
                          merge(can, soup_of(ring)),
                          1,
                          {"joined 2 overlapping parts into 1 solid"},
                          ""});
    }
    corpus.push_back({"terrain patch", terrain(24), 0, {}, "open sheet, not a solid"});
    {
        PolygonSoup s;
        s.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
        s.polygons = {{0, 1, 2}};
        corpus.push_back({"single triangle", s, 0, {}, "open sheet, not a solid"});
    }
    {
        PolygonSoup s = soup_of(test::make_uv_sphere(1.0, 24, 48));
        s = punched(s, Vec3(0, 0, 1), std::sqrt(2.0)); // the northern half gone: a bowl
        corpus.push_back({"bowl (half a sphere)", s, 0, {}, "open sheet, not a solid"});
    }
    {
        PolygonSoup s;
        for (int i = 0; i < 200; ++i)
            s.positions.push_back(Vec3(std::cos(i * 0.7), std::sin(i * 1.3), std::cos(i * 2.1)));
        corpus.push_back({"point cloud", s, 0, {}, "mesh has no faces"});
    }
    return corpus;
}

} // namespace zomeify::surface_test
