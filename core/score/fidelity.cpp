#include "core/score/fidelity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/anneal/random.h"
#include "core/base/errors.h"
#include "core/mesh/face_triangles.h"
#include "core/zome/real_sizes.h"

namespace zomeify {
namespace {

Vec3 to_mesh(const ZVec& p, const ModelTransform& t)
{
    const auto d = p.to_double();
    return {t.scale * d[0] + t.translation[0], t.scale * d[1] + t.translation[1], t.scale * d[2] + t.translation[2]};
}

// The model's faces as triangles in the mesh's coordinates (canonical split of every quad).
TriangleMesh model_surface(const ZomeModel& model)
{
    TriangleMesh out;
    for (const ZVec& p : model.nodes)
        out.positions.push_back(to_mesh(p, model.transform));
    for (const auto& face : model.faces)
    {
        if (face.size() != 3 && face.size() != 4)
            throw InvalidInputError("scoring needs faces of 3 or 4 corners");
        std::array<ZVec, 4> corners;
        std::array<uint32_t, 4> index{};
        for (size_t k = 0; k < face.size(); ++k)
        {
            if (face[k] >= model.nodes.size())
                throw InvalidInputError("a face of the model names a node it does not have");
            corners[k] = model.nodes[face[k]];
            index[k] = face[k];
        }
        const FaceTriangles t = face_triangles(std::span<const ZVec>(corners.data(), face.size()));
        for (int i = 0; i < t.count; ++i)
        {
            std::array<uint32_t, 3> tri{};
            for (int c = 0; c < 3; ++c)
                for (size_t k = 0; k < face.size(); ++k)
                    if (corners[k] == t.triangles[i][c])
                        tri[c] = index[k];
            out.triangles.push_back(tri);
        }
    }
    return out;
}

// Area-uniform random points of a triangle mesh: calls f(point) `count` times.
template <class F>
void sample_uniformly(const TriangleMesh& mesh, int count, Rng& rng, F&& f)
{
    std::vector<double> cumulative;
    cumulative.reserve(mesh.triangles.size());
    double total = 0.0;
    for (const auto& t : mesh.triangles)
    {
        const Vec3& a = mesh.positions[t[0]];
        total += 0.5 * (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a).norm();
        cumulative.push_back(total);
    }
    if (!(total > 0.0))
        return;
    for (int i = 0; i < count; ++i)
    {
        const double pick = rng.uniform01() * total;
        const size_t k = std::min<size_t>(
            static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()),
            cumulative.size() - 1);
        const auto& t = mesh.triangles[k];
        // Uniform in the triangle: u = √r1 spreads the points evenly from the corner a.
        const double u = std::sqrt(rng.uniform01()), v = rng.uniform01();
        f((1.0 - u) * mesh.positions[t[0]] + u * (1.0 - v) * mesh.positions[t[1]] + u * v * mesh.positions[t[2]]);
    }
}

OneWay distances(const TriangleMesh& from, const SurfaceProjector& to, double scale, int count, Rng& rng,
                 const FidelityOptions& options)
{
    OneWay w;
    double squares = 0.0;
    int n = 0;
    sample_uniformly(from, count, rng, [&](const Vec3& p) {
        if (options.radius > 0.0 && (p - options.near).squaredNorm() > options.radius * options.radius)
            return;
        const double d = (to.project(p).point - p).norm() / scale;
        squares += d * d;
        ++n;
        if (d > w.max)
        {
            w.max = d;
            w.farthest = p;
        }
    });
    w.rms = n > 0 ? std::sqrt(squares / n) : 0.0;
    return w;
}

std::string format(const char* pattern, double value)
{
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

} // namespace

std::string place_in_box(const Vec3& p, const Vec3& box_min, const Vec3& box_max)
{
    // Thirds of the box along each axis; the middle third says nothing.
    const auto third = [&](int k) {
        const double extent = box_max[k] - box_min[k];
        if (!(extent > 0.0))
            return 1;
        const double t = (p[k] - box_min[k]) / extent;
        return t < 1.0 / 3.0 ? 0 : (t > 2.0 / 3.0 ? 2 : 1);
    };
    static constexpr const char* kY[3] = {"bottom", "", "top"};
    static constexpr const char* kZ[3] = {"back", "", "front"};
    static constexpr const char* kX[3] = {"left", "", "right"};
    std::string out;
    for (const char* word : {kY[third(1)], kZ[third(2)], kX[third(0)]})
    {
        if (!*word)
            continue;
        if (!out.empty())
            out.push_back(' ');
        out.append(word);
    }
    return out.empty() ? std::string("middle") : out;
}

std::string place_on_surface(const Vec3& p, const TriangleMesh& surface)
{
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Vec3& q : surface.positions)
    {
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    return place_in_box(p, lo, hi);
}

Fidelity measure_fidelity(const ZomeModel& model, const SurfaceProjector& surface, const FidelityOptions& options)
{
    if (model.faces.empty())
        throw InvalidInputError("measuring the distance to a model needs its faces");
    const double scale = model.transform.scale;
    if (!(scale > 0.0) || !std::isfinite(scale))
        throw InvalidInputError("the model has no placement on the mesh (no transform)");
    const TriangleMesh faces = model_surface(model);
    const SurfaceProjector model_projector(faces);
    const int count = std::max(options.samples_per_side, 1);

    Fidelity f;
    Rng rng = Rng::for_stream(options.seed, 0);
    f.model_to_surface = distances(faces, surface, scale, count, rng, options);
    f.surface_to_model = distances(surface.mesh(), model_projector, scale, count, rng, options);
    const double m = f.model_to_surface.rms, s = f.surface_to_model.rms;
    f.rms_symmetric = std::sqrt(0.5 * (m * m + s * s));
    f.gap_is_missed_surface = f.surface_to_model.max >= f.model_to_surface.max;
    f.hausdorff = std::max(f.surface_to_model.max, f.model_to_surface.max);
    f.largest_gap_at = f.gap_is_missed_surface ? f.surface_to_model.farthest : f.model_to_surface.farthest;
    f.where = place_on_surface(f.largest_gap_at, surface.mesh());
    return f;
}

nlohmann::json fidelity_json(const Fidelity& f)
{
    const auto way = [](const OneWay& w) {
        return nlohmann::json{
            {"rms_b0", w.rms}, {"max_b0", w.max}, {"rms_mm", w.rms * kMmPerB0}, {"max_mm", w.max * kMmPerB0}};
    };
    return {{"model_to_surface", way(f.model_to_surface)},
            {"surface_to_model", way(f.surface_to_model)},
            {"rms_symmetric_b0", f.rms_symmetric},
            {"rms_symmetric_mm", f.rms_symmetric * kMmPerB0},
            {"hausdorff_b0", f.hausdorff},
            {"hausdorff_mm", f.hausdorff * kMmPerB0},
            {"largest_gap",
             {{"at", {f.largest_gap_at.x(), f.largest_gap_at.y(), f.largest_gap_at.z()}},
              {"kind", f.gap_is_missed_surface ? "surface missed by the model" : "model off the surface"},
              {"where", f.where}}},
            {"summary", fidelity_summary(f)}};
}

std::string fidelity_summary(const Fidelity& f)
{
    return "largest gap " + format("%.0f mm", f.hausdorff * kMmPerB0) + format(" (%.2f b0), ", f.hausdorff) +
           (f.gap_is_missed_surface ? "where the model misses the surface" : "where the model stands off the surface") +
           (f.where == "middle" ? ", in the middle" : ", at the " + f.where) + "; typical distance " +
           format("%.1f mm", f.rms_symmetric * kMmPerB0) + format(" (RMS %.3f b0)", f.rms_symmetric);
}

} // namespace zomeify
