// zomeify score MODEL --mesh MESH [--b0 LENGTH] [--samples N] [--near X,Y,Z --radius R] [--json]: how well a Zome model
// approximates a mesh, measured the same way for any model (energy terms, fold-overs, distances
// both ways in b0 and mm with where the largest gap is, clashes between parts).
// A model without a placement (a .vef from vZome) needs --b0, the mesh length of one b0 strut; its
// translation is then fitted. A model without faces gets them recovered from its struts.
#include <iomanip>
#include <iostream>
#include <sstream>

#include "core/base/errors.h"
#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/cli/point_arg.h"
#include "core/io/model_io.h"
#include "core/mesh/recover_faces.h"
#include "core/score/fit_translation.h"
#include "core/score/model_score.h"
#include "core/surface/prepare.h"
#include "core/zome/real_sizes.h"

namespace zomeify::cli {
namespace {

std::string fixed(double x, int digits)
{
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << x;
    return s.str();
}

std::string text_report(const ModelScore& s)
{
    std::string out;
    auto line = [&](const std::string& name, const std::string& value) { out += name + value + "\n"; };
    line("nodes            ", std::to_string(s.nodes));
    line("struts           ", std::to_string(s.struts));
    line("faces            ", std::to_string(s.faces) + " (" + std::to_string(s.triangles) + " triangles, " +
                                  std::to_string(s.quads) + " quads), genus " + std::to_string(s.genus));
    line("energy           ", std::to_string(s.energy.total) + " (distance " + std::to_string(s.energy.distance) +
                                  ", orientation " + std::to_string(s.energy.orientation) + ", fairing " +
                                  std::to_string(s.energy.fairing) + ", complexity " +
                                  std::to_string(s.energy.complexity) + ")");
    line("fold-overs       ", fold_over_summary(s.fold_overs));
    line("parts            ", clearance_summary(s.clearance));
    line("mirror           ", mirror_summary(s));
    const Fidelity& f = s.fidelity;
    const auto both = [](double b0) { return fixed(b0, 3) + " b0 = " + fixed(b0 * kMmPerB0, 1) + " mm"; };
    line("RMS distance     ", both(f.rms_symmetric) + " (model→mesh " + both(f.model_to_surface.rms) + ", mesh→model " +
                                  both(f.surface_to_model.rms) + ")");
    line("largest distance ",
         "model→mesh " + both(f.model_to_surface.max) + ", mesh→model " + both(f.surface_to_model.max));
    line("Hausdorff        ",
         both(f.hausdorff) + ", " +
             (f.gap_is_missed_surface ? "where the model misses the mesh" : "where the model stands off the mesh") +
             (f.where == "middle" ? ", in the middle" : ", at the " + f.where) + " (" + fixed(f.largest_gap_at.x(), 4) +
             ", " + fixed(f.largest_gap_at.y(), 4) + ", " + fixed(f.largest_gap_at.z(), 4) + ")");
    return out;
}

} // namespace

int cmd_score(const CommandArgs& argv)
{
    const Args args(argv, {"--mesh", "--b0", "--samples", "--near", "--radius"}, {"--json", "--thicken"});
    args.expect_positional(1, "one model file: zomeify score MODEL --mesh MESH [--b0 LENGTH] [--samples N] [--json]");
    const auto mesh_path = args.value("--mesh");
    if (!mesh_path)
        throw InvalidInputError("--mesh MESH is required: the surface to score the model against");
    ZomeModel model = read_model_file(args.positional()[0]);
    PrepareOptions prepare;
    prepare.thicken_sheets = args.has("--thicken"); // the surface the model was made for
    const SurfaceProjector surface(load_surface(*mesh_path, prepare));
    if (args.has("--b0"))
        model.transform = fit_translation(model, surface, args.number("--b0", 1.0, 1e-12, 1e12));
    else if (model.transform == ModelTransform{})
        throw InvalidInputError("the model has no placement on the mesh; give --b0 LENGTH (mesh units per b0 strut)");
    if (model.faces.empty())
    {
        std::vector<std::array<double, 3>> normals;
        for (const ZVec& p : model.nodes)
        {
            const auto d = p.to_double();
            const auto& t = model.transform;
            const Vec3 q(t.scale * d[0] + t.translation[0], t.scale * d[1] + t.translation[1],
                         t.scale * d[2] + t.translation[2]);
            const Vec3 n = surface.project(q).normal;
            normals.push_back({n.x(), n.y(), n.z()});
        }
        FaceRecovery faces = recover_faces(model, normals);
        if (!faces.ok)
            throw InvalidInputError("cannot recover the model's faces: " + faces.error);
        model.faces = std::move(faces.faces);
    }
    ScoreOptions options;
    options.fidelity.samples_per_side = static_cast<int>(args.integer("--samples", 50000, 100, 10000000));
    if (args.has("--near") != args.has("--radius"))
        throw InvalidInputError("give --near X,Y,Z and --radius R together (the distances near one point)");
    if (args.has("--near"))
    {
        options.fidelity.near = point_of(*args.value("--near"), "--near");
        options.fidelity.radius = args.number("--radius", 0.0, 1e-12, 1e300);
    }
    const ModelScore score = score_model(model, surface, options);
    std::cout << (args.has("--json") ? score_json(score) + "\n" : text_report(score));
    return 0;
}

} // namespace zomeify::cli
