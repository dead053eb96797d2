#include "core/anneal/engine/fold_overs.h"

#include "core/anneal/energy_samples.h"

#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"

namespace zomeify {

size_t count_fold_overs(const ZomeMesh& mesh, const SurfaceContext& context)
{
    size_t count = 0;
    for (Face f : faces(mesh))
    {
        LatticeSum sum;
        int corners = 0;
        Vec3 newell = Vec3::Zero();
        for (Halfedge h : face_halfedges(mesh, f))
        {
            const ZVec& a = mesh.position(mesh.from_vertex(h));
            const ZVec& b = mesh.position(mesh.to_vertex(h));
            sum += a;
            ++corners;
            const Vec3 pa = lattice_sum(a).divided(1), pb = lattice_sum(b).divided(1);
            newell += pa.cross(pb);
        }
        if (corners < 3)
            continue;
        const SurfaceSample s = context.sample(sum, corners);
        if (is_fold_over(newell, s.normal))
            ++count;
    }
    return count;
}

} // namespace zomeify
