#include "core/surface/weld.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

namespace zomeify {

namespace {

struct CellKey
{
    int64_t x, y, z;
    bool operator==(const CellKey&) const = default;
};

struct CellHash
{
    size_t operator()(const CellKey& k) const
    {
        // Large odd multipliers spread neighbouring cells over the table.
        uint64_t h = static_cast<uint64_t>(k.x) * 0x9E3779B97F4A7C15ull;
        h ^= static_cast<uint64_t>(k.y) * 0xC2B2AE3D27D4EB4Full + (h >> 29);
        h ^= static_cast<uint64_t>(k.z) * 0x165667B19E3779F9ull + (h >> 32);
        return static_cast<size_t>(h);
    }
};

constexpr uint32_t no_vertex = std::numeric_limits<uint32_t>::max();

// Exact duplicates: the bit patterns of the coordinates are the key (+0 and -0 made equal).
std::vector<uint32_t> weld_exact(const std::vector<Vec3>& positions, const std::vector<bool>& skip)
{
    std::vector<uint32_t> target(positions.size());
    std::unordered_map<CellKey, uint32_t, CellHash> first;
    first.reserve(positions.size());
    for (size_t i = 0; i < positions.size(); ++i)
    {
        target[i] = static_cast<uint32_t>(i);
        if (skip[i])
            continue;
        int64_t bits[3];
        for (int a = 0; a < 3; ++a)
        {
            const double v = positions[i][a] == 0.0 ? 0.0 : positions[i][a];
            std::memcpy(&bits[a], &v, sizeof v);
        }
        const auto [it, inserted] = first.try_emplace(CellKey{bits[0], bits[1], bits[2]}, static_cast<uint32_t>(i));
        if (!inserted)
            target[i] = it->second;
    }
    return target;
}

} // namespace

std::vector<uint32_t> weld_vertices(const std::vector<Vec3>& positions, double tolerance,
                                    const std::vector<bool>& skip)
{
    if (!(tolerance > 0))
        return weld_exact(positions, skip);

    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < positions.size(); ++i)
        if (!skip[i])
            lo = lo.cwiseMin(positions[i]);

    // Cells as wide as the tolerance: a partner is always in one of the 27 cells around a vertex.
    // Each cell keeps a linked list (head in the map, links in `next`) of the kept vertices in it.
    const double cell = tolerance;
    const double max_cell = 4e18;
    std::vector<uint32_t> target(positions.size());
    std::vector<uint32_t> next(positions.size(), no_vertex);
    std::unordered_map<CellKey, uint32_t, CellHash> head;
    head.reserve(positions.size());
    const double tol2 = tolerance * tolerance;
    for (size_t i = 0; i < positions.size(); ++i)
    {
        target[i] = static_cast<uint32_t>(i);
        if (skip[i])
            continue;
        const Vec3& p = positions[i];
        int64_t c[3];
        for (int a = 0; a < 3; ++a)
            c[a] = static_cast<int64_t>(std::min(std::floor((p[a] - lo[a]) / cell), max_cell));
        uint32_t found = no_vertex;
        for (int dx = -1; dx <= 1 && found == no_vertex; ++dx)
            for (int dy = -1; dy <= 1 && found == no_vertex; ++dy)
                for (int dz = -1; dz <= 1 && found == no_vertex; ++dz)
                {
                    const auto it = head.find(CellKey{c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it == head.end())
                        continue;
                    for (uint32_t j = it->second; j != no_vertex; j = next[j])
                        if ((positions[j] - p).squaredNorm() <= tol2 && (found == no_vertex || j < found))
                            found = j;
                }
        if (found != no_vertex)
        {
            target[i] = found;
            continue;
        }
        const auto [it, inserted] = head.try_emplace(CellKey{c[0], c[1], c[2]}, static_cast<uint32_t>(i));
        if (!inserted)
        {
            next[i] = it->second;
            it->second = static_cast<uint32_t>(i);
        }
    }
    return target;
}

} // namespace zomeify
