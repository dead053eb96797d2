#include "core/anneal/engine/seed_slabs.h"

#include <algorithm>
#include <array>
#include <utility>

#include "core/zome/qphi.h"

namespace zomeify {

namespace {

// The six 5-fold axes of the icosahedron, (0, ±1, φ) and its cyclic permutations: well spread,
// so successive sweeps cut the model along quite different planes.
constexpr std::array<std::array<double, 3>, 6> kDirections{
    {{0, 1, kPhi}, {0, -1, kPhi}, {1, kPhi, 0}, {-1, kPhi, 0}, {kPhi, 0, 1}, {-kPhi, 0, 1}}};

} // namespace

SlabPlan slab_plan(size_t nodes, int threads) noexcept
{
    SlabPlan plan;
    plan.slabs = std::max(4, threads);
    plan.epoch_proposals = std::max<uint64_t>(4096, 125 * static_cast<uint64_t>(nodes));
    return plan;
}

int slab_of_thread(uint64_t epoch, int index, int threads, int slabs) noexcept
{
    const uint64_t k = static_cast<uint64_t>(std::max(slabs, 1));
    const uint64_t spread = static_cast<uint64_t>(index) * k / static_cast<uint64_t>(std::max(threads, 1));
    return static_cast<int>((spread + epoch) % k);
}

std::vector<MeshIndex> seed_slab(const ZomeMesh& mesh, uint64_t epoch, int slab, int slabs)
{
    // One sweep (every slab once) per direction.
    const size_t k = static_cast<size_t>(std::max(slabs, 1));
    const auto& d = kDirections[(epoch / k) % kDirections.size()];
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
    const size_t n = nodes.size(), s = static_cast<size_t>(slab) % k;
    const size_t begin = n * s / k, end = n * (s + 1) / k;
    std::vector<MeshIndex> out;
    if (begin == end)
        return out;
    // The slab's members by two partial selections (O(n)), not a sort; ties in the projection are
    // broken by index, so the split is the same on every platform.
    std::nth_element(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(begin), nodes.end());
    std::nth_element(nodes.begin() + static_cast<std::ptrdiff_t>(begin),
                     nodes.begin() + static_cast<std::ptrdiff_t>(end - 1), nodes.end());
    out.reserve(end - begin);
    for (size_t i = begin; i < end; ++i)
        out.push_back(nodes[i].second);
    // nth_element leaves the members in an order of the standard library's choosing; seeds are
    // drawn by position in this list, so it must be canonical (native and wasm draw alike).
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace zomeify
