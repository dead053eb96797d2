#include "core/anneal/energy/element_energy.h"

#include <array>

#include "core/mesh/circulators.h"

namespace zomeify {

EnergyFixed node_distance_energy(const ZVec& p, const SurfaceContext& context, const EnergyOptions& options) noexcept
{
    return quantize(distance_value(context.node_sample(p), options));
}

StrutEnergy strut_energy(const ZVec& a, const ZVec& b, const SurfaceContext& context,
                         const EnergyOptions& options) noexcept
{
    // a + b is exact and symmetric in a and b, so both orientations of a strut agree.
    LatticeSum twice_mid = lattice_sum(a);
    twice_mid += b;
    const SurfaceSample mid = context.sample(twice_mid, 2, &a);
    StrutEnergy out;
    out.distance = quantize(distance_value(mid, options));
    out.tangential = quantize(tangential_value(difference(a, b), mid.normal));
    return out;
}

EnergyFixed corner_energy(const ZVec& prev, const ZVec& at, const ZVec& next, const Vec3& n_at) noexcept
{
    return quantize(corner_value(difference(at, next), difference(at, prev), n_at));
}

// The outward (Newell) normal of a face, summed from its smallest corner so that a face gives the
// same bits whichever corner a description starts from.
Vec3 newell_normal(std::span<const ZVec> corners) noexcept
{
    const size_t k = corners.size();
    size_t first = 0;
    for (size_t i = 1; i < k; ++i)
        if (corners[i] < corners[first])
            first = i;
    std::array<Vec3, 4> p;
    for (size_t i = 0; i < k && i < p.size(); ++i)
        p[i] = lattice_sum(corners[(first + i) % k]).divided(1);
    Vec3 newell = Vec3::Zero();
    for (size_t i = 0; i < k && i < p.size(); ++i)
        newell += p[i].cross(p[(i + 1) % k]);
    return newell;
}

FaceEnergy face_energy(std::span<const ZVec> corners, NodeNormals& normals, const EnergyOptions& options) noexcept
{
    FaceEnergy out;
    const size_t k = corners.size();
    LatticeSum sum;
    for (size_t i = 0; i < k; ++i)
    {
        sum += corners[i];
        out.normal += corner_energy(corners[(i + k - 1) % k], corners[i], corners[(i + 1) % k], normals.at(corners[i]));
    }
    out.corners = static_cast<int>(k);
    const SurfaceSample barycentre = normals.context().sample(sum, out.corners, &corners[0]);
    out.distance = quantize(distance_value(barycentre, options));
    out.fold_over = is_fold_over(newell_normal(corners), barycentre.normal);
    return out;
}

bool face_is_fold_over(std::span<const ZVec> corners, const SurfaceContext& context) noexcept
{
    LatticeSum sum;
    for (const ZVec& c : corners)
        sum += c;
    const SurfaceSample barycentre = context.sample(sum, static_cast<int>(corners.size()), &corners[0]);
    return is_fold_over(newell_normal(corners), barycentre.normal);
}

FaceEnergy face_energy(const ZomeMesh& mesh, Face f, NodeNormals& normals, const EnergyOptions& options) noexcept
{
    // Walks the face once: the corner at to_vertex(h) lies between from_vertex(h) and
    // to_vertex(next(h)). Same per-corner values as the span version, in another order, which the
    // exact integer sum does not see.
    FaceEnergy out;
    LatticeSum sum;
    const ZVec* first = nullptr;
    std::array<ZVec, 4> corners;
    for (Halfedge h : face_halfedges(mesh, f))
    {
        const ZVec& at = mesh.position(mesh.to_vertex(h));
        first = first ? first : &at;
        sum += at;
        out.normal += corner_energy(mesh.position(mesh.from_vertex(h)), at, mesh.position(mesh.to_vertex(mesh.next(h))),
                                    normals.at(at));
        if (static_cast<size_t>(out.corners) < corners.size())
            corners[static_cast<size_t>(out.corners)] = at;
        ++out.corners;
    }
    const SurfaceSample barycentre = normals.context().sample(sum, out.corners, first);
    out.distance = quantize(distance_value(barycentre, options));
    if (out.corners <= 4)
        out.fold_over = is_fold_over(
            newell_normal(std::span<const ZVec>(corners.data(), static_cast<size_t>(out.corners))), barycentre.normal);
    return out;
}

EnergyFixed fairing_energy(const ZVec& p, const LatticeSum& ring_sum, int ring_size) noexcept
{
    const LatticeSum excess = lattice_sum(p).times(ring_size) - ring_sum;
    return quantize(fairing_value(excess, ring_size));
}

EnergyFixed fairing_energy(const ZomeMesh& mesh, Vertex v) noexcept
{
    LatticeSum ring;
    int k = 0;
    for (Vertex w : adjacent_vertices(mesh, v))
    {
        ring += mesh.position(w);
        ++k;
    }
    return fairing_energy(mesh.position(v), ring, k);
}

} // namespace zomeify
