#include "core/anneal/energy/energy.h"

#include "core/anneal/energy/element_energy.h"
#include "core/anneal/energy/surface_distance.h"
#include "core/base/errors.h"
#include "core/mesh/element_ranges.h"

namespace zomeify {

EnergySums evaluate_local_sums(const ZomeMesh& mesh, const SurfaceContext& context, const EnergyOptions& options)
{
    if (options.w_complexity != 0.0 && options.target_nodes == 0)
    {
        throw InvalidInputError("energy: the complexity term needs a target node count (N_target > 0)");
    }
    EnergySums sums;
    for (Vertex v : vertices(mesh))
    {
        sums.distance += node_distance_energy(mesh.position(v), context, options);
        sums.fairing += fairing_energy(mesh, v);
        ++sums.nodes;
    }
    for (Edge e : edges(mesh))
    {
        const StrutEnergy s =
            strut_energy(mesh.position(mesh.vertex(e, 0)), mesh.position(mesh.vertex(e, 1)), context, options);
        sums.distance += s.distance;
        sums.tangential += s.tangential;
        ++sums.struts;
    }
    NodeNormals normals(context);
    for (Face f : faces(mesh))
    {
        // The list is sized for one local change, not a whole mesh: start afresh for every face.
        normals.clear();
        const FaceEnergy fe = face_energy(mesh, f, normals, options);
        sums.distance += fe.distance;
        sums.normal += fe.normal;
        sums.corners += fe.corners;
        sums.fold_overs += fe.fold_over ? 1 : 0;
        ++sums.faces;
    }
    return sums;
}

EnergyTerms evaluate_energy(const ZomeMesh& mesh, const SurfaceContext& context, const EnergyOptions& options)
{
    EnergySums sums = evaluate_local_sums(mesh, context, options);
    const SurfaceSums surface = evaluate_surface_distance(mesh, context, options);
    sums.surface = surface.sum;
    sums.surface_samples = surface.samples;
    return energy_terms(sums, options);
}

} // namespace zomeify
