#include "core/anneal/engine/fold_overs.h"

#include "core/anneal/energy/element_energy.h"
#include "core/mesh/element_ranges.h"

namespace zomeify {

std::vector<Face> fold_over_faces(const ZomeMesh& mesh, const SurfaceContext& context)
{
    // The energy's own test (face_energy), so a model's count is the sum E's fold-over term keeps.
    const EnergyOptions options;
    NodeNormals normals(context);
    std::vector<Face> out;
    for (Face f : faces(mesh))
    {
        normals.clear();
        if (face_energy(mesh, f, normals, options).fold_over)
            out.push_back(f);
    }
    return out;
}

size_t count_fold_overs(const ZomeMesh& mesh, const SurfaceContext& context)
{
    return fold_over_faces(mesh, context).size();
}

} // namespace zomeify
