// zomeify score MODEL --mesh MESH [--b0 LENGTH] [--json]: how well a Zome model approximates a
// mesh, measured the same way for any model (energy terms, fold-overs, symmetric distance in b0).
// A model without a placement (a .vef from vZome) needs --b0, the mesh length of one b0 strut; its
// translation is then fitted. A model without faces gets them recovered from its struts.
#include <iostream>

#include "core/base/errors.h"
#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/io/model_io.h"
#include "core/mesh/recover_faces.h"
#include "core/score/fit_translation.h"
#include "core/score/model_score.h"
#include "core/surface/prepare.h"

namespace zomeify::cli {
namespace {

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
    line("fold-overs       ", std::to_string(s.fold_overs));
    line("parts            ", clearance_summary(s.clearance));
    line("RMS distance     ", std::to_string(s.rms_symmetric) + " b0 (model→mesh " +
                                  std::to_string(s.rms_model_to_surface) + ", mesh→model " +
                                  std::to_string(s.rms_surface_to_model) + ")");
    line("Hausdorff        ", std::to_string(s.hausdorff) + " b0");
    return out;
}

} // namespace

int cmd_score(const CommandArgs& argv)
{
    const Args args(argv, {"--mesh", "--b0"}, {"--json"});
    args.expect_positional(1, "one model file: zomeify score MODEL --mesh MESH [--b0 LENGTH] [--json]");
    const auto mesh_path = args.value("--mesh");
    if (!mesh_path) throw InvalidInputError("--mesh MESH is required: the surface to score the model against");
    ZomeModel model = read_model_file(args.positional()[0]);
    const SurfaceProjector surface(load_surface(*mesh_path));
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
        if (!faces.ok) throw InvalidInputError("cannot recover the model's faces: " + faces.error);
        model.faces = std::move(faces.faces);
    }
    const ModelScore score = score_model(model, surface);
    std::cout << (args.has("--json") ? score_json(score) + "\n" : text_report(score));
    return 0;
}

} // namespace zomeify::cli
