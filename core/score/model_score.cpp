#include "core/score/model_score.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/anneal/energy.h"
#include "core/anneal/surface_context.h"
#include "core/base/errors.h"
#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"

namespace zomeify {
namespace {

//! Area-weighted squared distances of sample points to a surface, and their maximum.
struct DistanceSums
{
    double weighted_squares = 0.0, weight = 0.0, max_distance = 0.0;
    void add(double distance, double w)
    {
        weighted_squares += w * distance * distance;
        weight += w;
        max_distance = std::max(max_distance, distance);
    }
    double rms() const { return weight > 0 ? std::sqrt(weighted_squares / weight) : 0.0; }
};

//! Calls f(point, weight) for m² points at the centroids of the m×m sub-triangles of (a, b, c),
//! each weighted by its share of the area (deterministic, uniform over the triangle).
template <class F>
void sample_triangle(const Vec3& a, const Vec3& b, const Vec3& c, int m, F&& f)
{
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double w = area / (m * m);
    const Vec3 u = (b - a) / m, v = (c - a) / m;
    for (int i = 0; i < m; ++i)
        for (int j = 0; i + j < m; ++j)
        {
            const Vec3 o = a + i * u + j * v;
            f(o + (u + v) / 3.0, w); // upward sub-triangle
            if (i + j + 1 < m) f(o + 2.0 * (u + v) / 3.0, w); // downward one beside it
        }
}

Vec3 to_mesh(const ZVec& p, const ModelTransform& t)
{
    const auto d = p.to_double();
    return Vec3(t.scale * d[0] + t.translation[0], t.scale * d[1] + t.translation[1],
                t.scale * d[2] + t.translation[2]);
}

} // namespace

ModelScore score_model(const ZomeModel& model, const SurfaceProjector& surface, const ScoreOptions& options)
{
    if (model.faces.empty()) throw InvalidInputError("scoring needs the model's faces");
    const ZomeMesh mesh = from_model(model);
    const ValidationReport report = validate(mesh);
    if (!report.ok()) throw InvalidInputError("the model is not a valid closed Zome surface: " + report.message());

    ModelScore score;
    score.nodes = model.nodes.size();
    score.struts = model.struts.size();
    score.faces = model.faces.size();
    score.genus = report.genus;
    for (const auto& f : model.faces) (f.size() == 3 ? score.triangles : score.quads) += 1;
    for (Edge e : edges(mesh)) score.struts_by_kind[static_cast<size_t>(mesh.kind(e))] += 1;

    EnergyOptions energy = options.energy;
    if (energy.target_nodes == 0) energy.target_nodes = model.nodes.size();
    const SurfaceContext context(surface, model.transform);
    score.energy = evaluate_energy(mesh, context, energy);
    score.clearance = clearance_report(mesh);

    const double scale = model.transform.scale;
    const int m = std::max(1, static_cast<int>(std::lround(std::sqrt(options.samples_per_face))));
    TriangleMesh model_surface;
    for (const ZVec& p : model.nodes) model_surface.positions.push_back(to_mesh(p, model.transform));
    DistanceSums to_surface;
    for (const auto& face : model.faces)
    {
        const Vec3& a = model_surface.positions[face[0]];
        Vec3 newell = Vec3::Zero(), centre = Vec3::Zero();
        for (size_t k = 0; k < face.size(); ++k)
        {
            const Vec3& p = model_surface.positions[face[k]];
            const Vec3& q = model_surface.positions[face[(k + 1) % face.size()]];
            newell += p.cross(q);
            centre += p;
        }
        centre /= static_cast<double>(face.size());
        if (newell.dot(surface.project(centre).normal) < 0) ++score.fold_overs;
        for (size_t k = 1; k + 1 < face.size(); ++k)
        {
            const Vec3& b = model_surface.positions[face[k]];
            const Vec3& c = model_surface.positions[face[k + 1]];
            model_surface.triangles.push_back({face[0], face[k], face[k + 1]});
            sample_triangle(a, b, c, m, [&](const Vec3& p, double w) {
                to_surface.add((surface.project(p).point - p).norm() / scale, w);
            });
        }
    }
    const SurfaceProjector model_projector(model_surface);
    DistanceSums to_model;
    const TriangleMesh& s = surface.mesh();
    for (const auto& t : s.triangles)
        sample_triangle(s.positions[t[0]], s.positions[t[1]], s.positions[t[2]], 2, [&](const Vec3& p, double w) {
            to_model.add((model_projector.project(p).point - p).norm() / scale, w);
        });
    score.rms_model_to_surface = to_surface.rms();
    score.rms_surface_to_model = to_model.rms();
    score.rms_symmetric = std::sqrt(0.5 * (score.rms_model_to_surface * score.rms_model_to_surface +
                                           score.rms_surface_to_model * score.rms_surface_to_model));
    score.hausdorff = std::max(to_surface.max_distance, to_model.max_distance);
    return score;
}

std::string score_json(const ModelScore& score)
{
    nlohmann::ordered_json j;
    j["nodes"] = score.nodes;
    j["struts"] = score.struts;
    nlohmann::ordered_json kinds;
    for (int k = 0; k < kStrutKindCount; ++k)
        kinds[std::string(kind_info(static_cast<StrutKind>(k)).name)] = score.struts_by_kind[static_cast<size_t>(k)];
    j["struts_by_kind"] = kinds;
    j["faces"] = {{"total", score.faces}, {"triangles", score.triangles}, {"quads", score.quads}};
    j["genus"] = score.genus;
    const EnergyTerms& e = score.energy;
    j["energy"] = {{"total", e.total},           {"distance", e.distance}, {"orientation", e.orientation},
                   {"tangential", e.tangential}, {"normal", e.normal},     {"fairing", e.fairing},
                   {"complexity", e.complexity}};
    j["fold_overs"] = score.fold_overs;
    const ClearanceReport& c = score.clearance;
    nlohmann::ordered_json clashes;
    for (int k = 1; k < kClashKinds; ++k)
        clashes[clash_name(static_cast<ClashKind>(k))] = c.clashes[static_cast<size_t>(k)];
    j["clearance"] = {{"clashes", c.total()},
                      {"by_kind", clashes},
                      {"smallest_b0", {{"ball_ball", c.ball_ball}, {"ball_strut", c.ball_strut}, {"strut_strut", c.strut_strut}}},
                      {"summary", clearance_summary(c)}};
    j["distance_b0"] = {{"rms_model_to_surface", score.rms_model_to_surface},
                        {"rms_surface_to_model", score.rms_surface_to_model},
                        {"rms_symmetric", score.rms_symmetric},
                        {"hausdorff", score.hausdorff}};
    return j.dump(2);
}

} // namespace zomeify
