#include "core/anneal/engine/seed_slabs.h"

#include <algorithm>
#include <array>
#include <utility>

namespace zomeify {

namespace {

// The six 5-fold axes of the icosahedron, (0, ±1, φ) and its cyclic permutations: well spread,
// so successive epochs cut the model along quite different planes.
constexpr double kPhi = 1.6180339887498949;
constexpr std::array<std::array<double, 3>, 6> kDirections{{
    {0, 1, kPhi}, {0, -1, kPhi}, {1, kPhi, 0}, {-1, kPhi, 0}, {kPhi, 0, 1}, {-kPhi, 0, 1}}};

} // namespace

std::vector<MeshIndex> seed_slab(const ZomeMesh& mesh, uint64_t epoch, int index, int threads)
{
    const auto& d = kDirections[epoch % kDirections.size()];
    std::vector<std::pair<double, MeshIndex>> nodes;
    nodes.reserve(mesh.n_vertices());
    for (MeshIndex i = 0; i < mesh.vertices_size(); ++i)
    {
        const Vertex v(i);
        if (mesh.is_deleted(v))
            continue;
        const auto p = mesh.position(v).to_double();
        nodes.emplace_back(d[0] * p[0] + d[1] * p[1] + d[2] * p[2], i);
    }
    const size_t n = nodes.size(), t = static_cast<size_t>(std::max(threads, 1));
    // The slab a thread gets moves on with the epoch too.
    const size_t slab = (static_cast<size_t>(index) + epoch / kDirections.size()) % t;
    const size_t begin = n * slab / t, end = n * (slab + 1) / t;
    std::vector<MeshIndex> out;
    if (begin == end)
        return out;
    // The slab's members by two partial selections (O(n)), not a sort.
    std::nth_element(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(begin), nodes.end());
    std::nth_element(nodes.begin() + static_cast<std::ptrdiff_t>(begin),
                     nodes.begin() + static_cast<std::ptrdiff_t>(end - 1), nodes.end());
    out.reserve(end - begin);
    for (size_t k = begin; k < end; ++k) out.push_back(nodes[k].second);
    return out;
}

} // namespace zomeify
