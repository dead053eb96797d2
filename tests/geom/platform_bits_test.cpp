// Native and wasm must compute the same bits: the annealer's decisions and the energy the page
// shows depend on them (e2e/golden.spec.js compares the page's energy with the native CLI's).
// Hashes of each stage on the shared torus (prepared positions, vertex and face normals, π(p) of a
// grid of points) against one golden value that both builds must reach. Two causes found so far:
// Eigen's SSE reductions (Vector3d norms summed in another order than scalar Eigen) and libm's
// atan2 (glibc and musl differ in the last bit). If this fails on one platform only, the printed
// stage hashes say where the bits part; if it fails on both with equal output, a change of the
// geometry moved the golden value: update it.
#include <cstdint>
#include <cstring>
#include <iostream>

#include <gtest/gtest.h>

#include "core/geom/closest_point.h"
#include "core/surface/prepare.h"
#include "tests/geom/geom_reference.h"
#include "tests/support/paths.h"

namespace zomeify {
namespace {

constexpr uint64_t kTorusGolden = 0x7a842b9c0930a0a2ull;

struct BitHash
{
    uint64_t h = 1469598103934665603ull;
    void add(double x)
    {
        uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        for (int i = 0; i < 8; ++i)
            h = (h ^ ((b >> (8 * i)) & 0xff)) * 1099511628211ull;
    }
    void add(const Vec3& v)
    {
        add(v.x());
        add(v.y());
        add(v.z());
    }
};

TEST(GeomPlatformBits, TorusStagesAreTheSameBitsOnEveryPlatform)
{
    ZOME_REQUIRE_SHARED();
    const TriangleMesh mesh = load_surface(test::shared_mesh_path("torus.obj"));
    BitHash positions;
    for (const Vec3& v : mesh.positions)
        positions.add(v);
    const SurfaceProjector projector(mesh);
    BitHash normals;
    for (const Vec3& n : projector.vertex_normals())
        normals.add(n);
    BitHash faces;
    for (const Vec3& n : projector.face_normals())
        faces.add(n);
    BitHash answers, dists, points;
    Vec3 lo = mesh.positions[0], hi = lo;
    for (const Vec3& v : mesh.positions)
    {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j)
            for (int k = 0; k <= 20; ++k)
            {
                const Vec3 p(lo.x() + (hi.x() - lo.x()) * i / 20.0, lo.y() + (hi.y() - lo.y()) * j / 20.0,
                             lo.z() + (hi.z() - lo.z()) * k / 20.0);
                const ClosestPoint c = projector.project(p);
                dists.add(c.distance_squared);
                points.add(c.point);
                answers.add(c.normal);
                answers.add(static_cast<double>(c.triangle));
            }
    std::cout << std::hex << "positions " << positions.h << " vnormals " << normals.h << " fnormals " << faces.h
              << " dist " << dists.h << " points " << points.h << " normals+tri " << answers.h << std::dec << "\n";
    BitHash all;
    for (const uint64_t h : {positions.h, normals.h, faces.h, dists.h, points.h, answers.h})
        all.add(static_cast<double>(h >> 11)); // exact in a double
    EXPECT_EQ(all.h, kTorusGolden) << std::hex << "got 0x" << all.h;
}

} // namespace
} // namespace zomeify
