#include "tests/support/generated_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace zomeify::test {
namespace {

constexpr double kPi = std::numbers::pi;

// The 12 even permutations of (0, 1, 2, 3): a positively oriented tetrahedron stays positive.
constexpr std::array<std::array<int, 4>, 12> kEven = {{{0, 1, 2, 3},
                                                       {0, 2, 3, 1},
                                                       {0, 3, 1, 2},
                                                       {1, 0, 3, 2},
                                                       {1, 2, 0, 3},
                                                       {1, 3, 2, 0},
                                                       {2, 0, 1, 3},
                                                       {2, 1, 3, 0},
                                                       {2, 3, 0, 1},
                                                       {3, 0, 2, 1},
                                                       {3, 1, 0, 2},
                                                       {3, 2, 1, 0}}};

double torus_distance(const Vec3& p, const Vec3& centre, double major, double minor)
{
    const Vec3 q = p - centre; // around the z axis
    return std::hypot(std::hypot(q.x(), q.y()) - major, q.z()) - minor;
}

Vec3 trefoil(double t)
{
    return {std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t)};
}

double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * ab)).norm();
}

std::pair<Vec3, Vec3> box_of(const TriangleMesh& m)
{
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const Vec3& p : m.positions)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return {lo, hi};
}

GeneratedShape finish(std::string name, TriangleMesh mesh, long long genus, double thinnest, double gap)
{
    const auto [lo, hi] = box_of(mesh);
    return {std::move(name), std::move(mesh), genus, (hi - lo).maxCoeff(), thinnest, gap};
}

} // namespace

TriangleMesh polygonise(const std::function<double(const Vec3&)>& distance, const Vec3& lo, const Vec3& hi, int cells)
{
    const double h = (hi - lo).maxCoeff() / cells;
    std::array<int, 3> n{};
    for (int k = 0; k < 3; ++k)
        n[k] = std::max(1, static_cast<int>(std::ceil((hi[k] - lo[k]) / h))) + 1; // grid points per axis
    const auto id = [&](int i, int j, int k) { return (static_cast<int64_t>(k) * n[1] + j) * n[0] + i; };
    const auto point = [&](int64_t v) {
        const int64_t i = v % n[0], j = (v / n[0]) % n[1], k = v / (static_cast<int64_t>(n[0]) * n[1]);
        return Vec3(lo.x() + i * h, lo.y() + j * h, lo.z() + k * h);
    };
    std::vector<double> f(static_cast<size_t>(n[0]) * n[1] * n[2]);
    for (size_t v = 0; v < f.size(); ++v)
    {
        const double d = distance(point(static_cast<int64_t>(v)));
        f[v] = d == 0.0 ? 1e-12 : d; // no zero at a grid point: every cut is strictly inside an edge
    }
    TriangleMesh m;
    std::unordered_map<int64_t, uint32_t> cut_ids; // edge (a, b), a < b → vertex
    const int64_t count = static_cast<int64_t>(f.size());
    const auto cut = [&](int64_t a, int64_t b) {
        const int64_t key = std::min(a, b) * count + std::max(a, b);
        auto [it, added] = cut_ids.try_emplace(key, static_cast<uint32_t>(m.positions.size()));
        if (added)
        {
            // Kept off the grid points, so no two cut points nearly coincide.
            const double t = std::clamp(f[a] / (f[a] - f[b]), 0.05, 0.95);
            m.positions.push_back(point(a) + t * (point(b) - point(a)));
        }
        return it->second;
    };
    // Kuhn's six tetrahedra of the unit cube: 0 → one axis → two axes → 7, corners as bit masks.
    constexpr std::array<std::array<int, 3>, 6> axes = {
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    for (int k = 0; k + 1 < n[2]; ++k)
        for (int j = 0; j + 1 < n[1]; ++j)
            for (int i = 0; i + 1 < n[0]; ++i)
                for (const auto& a : axes)
                {
                    std::array<int, 4> bits = {0, 1 << a[0], (1 << a[0]) | (1 << a[1]), 7};
                    // Odd axis permutations give negatively oriented tetrahedra: swap two corners.
                    const bool odd = (a[0] == 0 && a[1] == 2) || (a[0] == 1 && a[1] == 0) || (a[0] == 2 && a[1] == 1);
                    if (odd)
                        std::swap(bits[1], bits[2]);
                    std::array<int64_t, 4> v{};
                    int inside = 0;
                    for (int c = 0; c < 4; ++c)
                    {
                        v[c] = id(i + (bits[c] & 1), j + ((bits[c] >> 1) & 1), k + ((bits[c] >> 2) & 1));
                        inside += f[v[c]] < 0 ? 1 : 0;
                    }
                    if (inside == 0 || inside == 4)
                        continue;
                    const auto in = [&](int c) { return f[v[c]] < 0; };
                    for (const auto& p : kEven)
                    {
                        const int64_t a0 = v[p[0]], a1 = v[p[1]], a2 = v[p[2]], a3 = v[p[3]];
                        if (inside == 1 && in(p[0]))
                            m.triangles.push_back({cut(a0, a1), cut(a0, a2), cut(a0, a3)});
                        else if (inside == 3 && !in(p[0]))
                            m.triangles.push_back({cut(a0, a1), cut(a0, a3), cut(a0, a2)});
                        else if (inside == 2 && in(p[0]) && in(p[1]))
                        {
                            const uint32_t q[4] = {cut(a0, a2), cut(a0, a3), cut(a1, a3), cut(a1, a2)};
                            m.triangles.push_back({q[0], q[1], q[2]});
                            m.triangles.push_back({q[0], q[2], q[3]});
                        }
                        else
                            continue;
                        break;
                    }
                }
    return m;
}

GeneratedShape make_trefoil_tube(double gap_over_thickness)
{
    constexpr int kSegments = 240;
    std::vector<Vec3> curve;
    for (int i = 0; i < kSegments; ++i)
        curve.push_back(trefoil(2 * kPi * i / kSegments));
    // The closest approach of two strands (points at least 0.5 apart in the parameter; nearer ones
    // are on one strand, the curve's radius of curvature being 1.29 at least).
    double strands = 1e300;
    for (int i = 0; i < kSegments; ++i)
        for (int j = i + 1; j < kSegments; ++j)
            if (std::min(j - i, kSegments - (j - i)) * 2 * kPi / kSegments >= 0.5)
                strands = std::min(strands, (curve[i] - curve[j]).norm());
    // thickness 2r and gap strands - 2r = gap_over_thickness * 2r.
    const double r = strands / (2.0 * (1.0 + gap_over_thickness));
    // Runs of 12 segments in bounding spheres: a run farther than the nearest segment so far is skipped.
    constexpr int kRun = 12;
    std::vector<std::pair<Vec3, double>> spheres;
    for (int s = 0; s < kSegments; s += kRun)
    {
        Vec3 c = Vec3::Zero();
        for (int i = s; i <= s + kRun; ++i)
            c += curve[i % kSegments];
        c /= kRun + 1;
        double rad = 0.0;
        for (int i = s; i <= s + kRun; ++i)
            rad = std::max(rad, (curve[i % kSegments] - c).norm());
        spheres.push_back({c, rad});
    }
    const auto distance = [&](const Vec3& p) {
        double d = 1e300;
        for (int s = 0; s < kSegments; s += kRun)
        {
            const auto& [c, rad] = spheres[static_cast<size_t>(s / kRun)];
            if ((p - c).norm() - rad >= d)
                continue;
            for (int i = s; i < s + kRun; ++i)
                d = std::min(d, segment_distance(p, curve[i], curve[(i + 1) % kSegments]));
        }
        return d - r;
    };
    const Vec3 pad = Vec3::Constant(r + 0.2);
    TriangleMesh mesh = polygonise(distance, Vec3(-3, -3, -1) - pad, Vec3(3, 3, 1) + pad, 90);
    return finish("trefoil", std::move(mesh), 1, 2 * r, strands - 2 * r);
}

GeneratedShape make_double_torus()
{
    // Two tori of tube radius 0.35 whose centre circles touch at the origin: one joint, genus 2.
    constexpr double R = 1.0, r = 0.35;
    const auto distance = [&](const Vec3& p) {
        return std::min(torus_distance(p, Vec3(-R, 0, 0), R, r), torus_distance(p, Vec3(R, 0, 0), R, r));
    };
    const Vec3 ext(2 * R + r + 0.15, R + r + 0.15, r + 0.15);
    TriangleMesh mesh = polygonise(distance, -ext, ext, 90);
    return finish("double_torus", std::move(mesh), 2, 2 * r, 2 * (R - r));
}

GeneratedShape make_mug(double handle_cells)
{
    // A cup of outer radius 1 and height 2.2 (axis y), walls 0.16 thick; the handle is a ring in the
    // xy plane centred on the wall, cut off inside the wall so it does not reach into the cup.
    constexpr double ro = 1.0, height = 2.2, wall = 0.16, ring = 0.6;
    // Longest side (x): from -ro to the ring's outer edge, 2 ro + ring + rh = 2 handle_cells rh.
    const double rh = (2 * ro + ring) / (2 * handle_cells - 1);
    const auto distance = [&](const Vec3& p) {
        const double radial = std::hypot(p.x(), p.z());
        const double outer = std::max(radial - ro, std::abs(p.y() - height / 2) - height / 2);
        const double inner = std::max(radial - (ro - wall), wall - p.y()); // open at the top
        const double cup = std::max(outer, -inner);
        const double handle = std::max(torus_distance(Vec3(p.x(), p.y(), p.z()), Vec3(ro, height / 2, 0), ring, rh),
                                       ro - wall / 2 - p.x());
        return std::min(cup, handle);
    };
    const Vec3 lo(-ro - 0.15, -0.15, -ro - 0.15), hi(ro + ring + rh + 0.15, height + 0.15, ro + 0.15);
    TriangleMesh mesh = polygonise(distance, lo, hi, 90);
    return finish("mug", std::move(mesh), 1, 2 * rh, ring - rh);
}

GeneratedShape make_car()
{
    // Rounded boxes (half sizes, rounding radius) for the body and the cabin; wheels are discs of
    // radius 0.42 and half width 0.14 whose inner faces sink into the body.
    const auto rounded_box = [](const Vec3& p, const Vec3& centre, const Vec3& half, double round) {
        const Vec3 q = (p - centre).cwiseAbs() - (half - Vec3::Constant(round));
        return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0) - round;
    };
    const auto wheel = [](const Vec3& p, const Vec3& centre) {
        const Vec3 q = p - centre; // axis z
        const double radial = std::hypot(q.x(), q.y()) - 0.42, axial = std::abs(q.z()) - 0.14;
        return std::hypot(std::max(radial, 0.0), std::max(axial, 0.0)) + std::min(std::max(radial, axial), 0.0);
    };
    const auto distance = [&](const Vec3& p) {
        double d = rounded_box(p, Vec3(0, 0.8, 0), Vec3(2.0, 0.38, 0.85), 0.15);
        d = std::min(d, rounded_box(p, Vec3(-0.25, 1.4, 0), Vec3(1.0, 0.32, 0.72), 0.2));
        for (const double x : {-1.3, 1.3})
            for (const double z : {-0.8, 0.8})
                d = std::min(d, wheel(p, Vec3(x, 0.42, z)));
        return d;
    };
    const Vec3 lo(-2.15, -0.15, -1.1), hi(2.15, 1.9, 1.1);
    TriangleMesh mesh = polygonise(distance, lo, hi, 96);
    return finish("car", std::move(mesh), 0, 0.28, 0.0);
}

const std::vector<GeneratedShape>& generated_shapes()
{
    static const std::vector<GeneratedShape> shapes = {make_trefoil_tube(), make_double_torus(), make_mug()};
    return shapes;
}

} // namespace zomeify::test
