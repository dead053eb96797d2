#include "core/score/fold_over_report.h"

#include <utility>

#include "core/anneal/engine/fold_overs.h"
#include "core/mesh/circulators.h"
#include "core/score/fidelity.h"

namespace zomeify {

FoldOverReport fold_over_report(const ZomeMesh& mesh, const SurfaceContext& context)
{
    FoldOverReport report;
    for (Face f : fold_over_faces(mesh, context))
    {
        Vec3 sum = Vec3::Zero();
        int n = 0;
        for (Vertex v : face_vertices(mesh, f))
        {
            const auto d = mesh.position(v).to_double();
            sum += Vec3(d[0], d[1], d[2]);
            ++n;
        }
        report.points.push_back(context.to_mesh(sum / n));
    }
    for (const Vec3& p : report.points)
        report.places.push_back(place_on_surface(p, context.projector().mesh()));
    return report;
}

std::string fold_over_summary(const FoldOverReport& report)
{
    const size_t n = report.count();
    std::string out = std::to_string(n) + (n == 1 ? " fold-over" : " fold-overs");
    if (n == 0)
        return out;
    // Places in the order they first appear, each with its count.
    std::vector<std::pair<std::string, int>> places;
    for (const std::string& place : report.places)
    {
        auto it = places.begin();
        while (it != places.end() && it->first != place)
            ++it;
        if (it == places.end())
            places.emplace_back(place, 1);
        else
            ++it->second;
    }
    out += " (";
    for (size_t i = 0; i < places.size(); ++i)
    {
        const auto& [place, count] = places[i];
        out += (i ? ", " : "") + (count > 1 ? std::to_string(count) + " " : std::string()) +
               (place == "middle" ? "in the middle" : "at the " + place);
    }
    return out + ")";
}

nlohmann::json fold_over_places_json(const FoldOverReport& report)
{
    nlohmann::json places = nlohmann::json::array();
    for (size_t i = 0; i < report.points.size(); ++i)
    {
        const Vec3& p = report.points[i];
        places.push_back({{"where", report.places[i]}, {"at", {p.x(), p.y(), p.z()}}});
    }
    return places;
}

} // namespace zomeify
