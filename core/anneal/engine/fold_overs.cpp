#include "core/anneal/engine/fold_overs.h"

#include "core/anneal/element_energy.h"
#include "core/mesh/element_ranges.h"

namespace zomeify {

size_t count_fold_overs(const ZomeMesh& mesh, const SurfaceContext& context)
{
    // The energy's own test (face_energy), so a model's count is the sum E's fold-over term keeps.
    const EnergyOptions options;
    NodeNormals normals(context);
    size_t count = 0;
    for (Face f : faces(mesh))
    {
        normals.clear();
        count += face_energy(mesh, f, normals, options).fold_over ? 1 : 0;
    }
    return count;
}

} // namespace zomeify
