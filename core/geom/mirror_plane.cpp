#include "core/geom/mirror_plane.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/base/errors.h"

namespace zomeify {

namespace {

// Points spread evenly over the surface without random numbers: the i-th of n falls in the triangle
// that holds the fraction (i + ½)/n of the total area, at a position of the R2 sequence (the plastic
// number's multiples), so the same surface always gives the same points natively and in wasm.
std::vector<Vec3> even_points(const TriangleMesh& mesh, int count)
{
    std::vector<double> cumulative;
    cumulative.reserve(mesh.triangles.size());
    double total = 0.0;
    for (const auto& t : mesh.triangles)
    {
        const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        total += 0.5 * (b - a).cross(c - a).norm();
        cumulative.push_back(total);
    }
    if (!(total > 0.0) || !std::isfinite(total))
        throw InvalidInputError("the surface has no area, so it has no mirror plane");
    constexpr double kPlastic = 1.32471795724474602596;
    constexpr double kA1 = 1.0 / kPlastic, kA2 = 1.0 / (kPlastic * kPlastic);
    std::vector<Vec3> points;
    points.reserve(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i)
    {
        const double at = (i + 0.5) / count * total;
        const size_t k = std::min<size_t>(
            static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin()),
            cumulative.size() - 1);
        double r1 = std::fmod(0.5 + i * kA1, 1.0), r2 = std::fmod(0.5 + i * kA2, 1.0);
        if (r1 + r2 > 1.0)
        {
            r1 = 1.0 - r1;
            r2 = 1.0 - r2;
        }
        const auto& t = mesh.triangles[k];
        const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        points.push_back(a + r1 * (b - a) + r2 * (c - a));
    }
    return points;
}

double mean_squared_gap(const SurfaceProjector& surface, const std::vector<Vec3>& points, const Vec3& n, double offset)
{
    double sum = 0.0;
    for (const Vec3& p : points)
        sum += surface.project(p - 2.0 * (n.dot(p) - offset) * n).distance_squared;
    return sum / static_cast<double>(points.size());
}

// Directions spread evenly over the hemisphere z ≥ 0 (a Fibonacci spiral): a plane and its
// opposite normal are the same plane.
std::vector<Vec3> hemisphere(int count)
{
    std::vector<Vec3> out;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i)
    {
        const double z = (i + 0.5) / count;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    }
    return out;
}

struct Candidate
{
    Vec3 normal;
    double offset;
    double score; // mean squared gap
};

// Turns of the normal and shifts of the plane, halved whenever none of the six moves helps.
Candidate refine(const SurfaceProjector& surface, const std::vector<Vec3>& points, Candidate c, const Vec3& centre,
                 double diagonal)
{
    double angle = 4.0 * std::numbers::pi / 180.0, shift = 0.01 * diagonal;
    for (int round = 0; round < 200 && angle > 0.02 * std::numbers::pi / 180.0; ++round)
    {
        const Vec3 t1 = c.normal.unitOrthogonal(), t2 = c.normal.cross(t1);
        Candidate best = c;
        auto offer = [&](const Vec3& n, double offset) {
            const double s = mean_squared_gap(surface, points, n, offset);
            if (s < best.score)
                best = {n, offset, s};
        };
        for (const Vec3& t : {t1, t2})
            for (double sign : {-1.0, 1.0})
            {
                // Turned about the plane's point nearest the centroid, so a turn is not also a shift.
                const Vec3 n = (c.normal * std::cos(angle) + sign * t * std::sin(angle)).normalized();
                const Vec3 pivot = centre - (c.normal.dot(centre) - c.offset) * c.normal;
                offer(n, n.dot(pivot));
            }
        for (double sign : {-1.0, 1.0})
            offer(c.normal, c.offset + sign * shift);
        if (best.score < c.score)
            c = best;
        else
        {
            angle *= 0.5;
            shift *= 0.5;
        }
    }
    return c;
}

} // namespace

MirrorPlane measure_mirror_plane(const SurfaceProjector& surface, const Vec3& normal, double offset, int points)
{
    const std::vector<Vec3> at = even_points(surface.mesh(), std::max(points, 1));
    MirrorPlane m;
    const double length = normal.norm();
    if (!(length > 0.0) || !std::isfinite(length))
        throw InvalidInputError("a mirror plane needs a nonzero normal");
    m.normal = normal / length;
    m.offset = offset / length;
    Eigen::AlignedBox3d box;
    for (const Vec3& p : surface.mesh().positions)
        box.extend(p);
    m.diagonal = box.diagonal().norm();
    std::vector<double> gaps;
    gaps.reserve(at.size());
    double sum = 0.0;
    for (const Vec3& p : at)
    {
        const double d2 = surface.project(m.reflect(p)).distance_squared;
        sum += d2;
        gaps.push_back(std::sqrt(d2));
    }
    std::sort(gaps.begin(), gaps.end());
    m.rms = std::sqrt(sum / static_cast<double>(gaps.size()));
    m.p95 = gaps[std::min(gaps.size() - 1, static_cast<size_t>(0.95 * static_cast<double>(gaps.size())))];
    m.max = gaps.back();
    return m;
}

MirrorPlane find_mirror_plane(const SurfaceProjector& surface, const MirrorPlaneOptions& options)
{
    const TriangleMesh& mesh = surface.mesh();
    const std::vector<Vec3> points = even_points(mesh, std::max(options.search_points, 16));
    Vec3 centre = Vec3::Zero();
    for (const Vec3& p : points)
        centre += p;
    centre /= static_cast<double>(points.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const Vec3& p : points)
        covariance += (p - centre) * (p - centre).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(covariance);
    Eigen::AlignedBox3d box;
    for (const Vec3& p : mesh.positions)
        box.extend(p);
    const double diagonal = box.diagonal().norm();

    std::vector<Vec3> normals = {axes.eigenvectors().col(0),
                                 axes.eigenvectors().col(1),
                                 axes.eigenvectors().col(2),
                                 Vec3::UnitX(),
                                 Vec3::UnitY(),
                                 Vec3::UnitZ()};
    for (const Vec3& n : hemisphere(128))
        normals.push_back(n);
    std::vector<Candidate> scored;
    for (const Vec3& raw : normals)
    {
        const Vec3 n = raw.normalized();
        scored.push_back({n, n.dot(centre), mean_squared_gap(surface, points, n, n.dot(centre))});
    }
    std::sort(scored.begin(), scored.end(), [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
    // The best few that are not the same plane (normals more than 10° apart) are refined.
    std::vector<Candidate> seeds;
    for (const Candidate& c : scored)
    {
        const bool distinct = std::all_of(seeds.begin(), seeds.end(), [&](const Candidate& s) {
            return std::abs(s.normal.dot(c.normal)) < std::cos(10.0 * std::numbers::pi / 180.0);
        });
        if (distinct)
            seeds.push_back(c);
        if (seeds.size() == 3)
            break;
    }
    Candidate best = seeds.front();
    for (const Candidate& s : seeds)
    {
        const Candidate r = refine(surface, points, s, centre, diagonal);
        if (r.score < best.score)
            best = r;
    }
    // A canonical sign: the largest component of the normal positive.
    Eigen::Index largest = 0;
    best.normal.cwiseAbs().maxCoeff(&largest);
    if (best.normal[largest] < 0.0)
    {
        best.normal = -best.normal;
        best.offset = -best.offset;
    }
    return measure_mirror_plane(surface, best.normal, best.offset, options.final_points);
}

} // namespace zomeify
