#pragma once
//! \file fold_over_report.h
//! The fold-overs a finished model still has, for users: how many, and where on the shape (in
//! the words of fidelity.h's place_in_box), so a builder knows which panels to look at.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/anneal/energy/surface_context.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

struct FoldOverReport
{
    std::vector<Vec3> points;        //!< barycentres of the fold-over faces, in the mesh's units
    std::vector<std::string> places; //!< the same, in words ("top left", "middle"), in S's box
    size_t count() const noexcept { return points.size(); }
};

//! The faces count_fold_overs() counts (the energy's own test), placed on S.
FoldOverReport fold_over_report(const ZomeMesh& mesh, const SurfaceContext& context);

//! "0 fold-overs", "1 fold-over (at the top left)", "3 fold-overs (2 at the left, 1 in the middle)".
std::string fold_over_summary(const FoldOverReport& report);

//! [{"where": "top left", "at": [x, y, z]}, ...] (mesh units), the --stats "fold_over_places".
nlohmann::json fold_over_places_json(const FoldOverReport& report);

} // namespace zomeify
