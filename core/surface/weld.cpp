#include "core/surface/weld.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

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
        // Final avalanche, so that the low bits the table uses depend on every input bit.
        h ^= h >> 33;
        h *= 0xFF51AFD7ED558CCDull;
        h ^= h >> 33;
        return static_cast<size_t>(h);
    }
};

constexpr uint32_t no_vertex = std::numeric_limits<uint32_t>::max();

// Open addressing with linear probing: one flat allocation, no per-entry nodes, which matters
// when every vertex of a million-vertex mesh is inserted.
class CellTable
{
public:
    explicit CellTable(size_t expected)
    {
        size_t capacity = 16;
        while (capacity < 2 * expected)
            capacity *= 2;
        keys_.resize(capacity);
        values_.assign(capacity, no_vertex);
    }
    //! The head stored for `key`, or no_vertex.
    uint32_t find(const CellKey& key) const
    {
        for (size_t i = CellHash{}(key) & (keys_.size() - 1);; i = (i + 1) & (keys_.size() - 1))
        {
            if (values_[i] == no_vertex)
                return no_vertex;
            if (keys_[i] == key)
                return values_[i];
        }
    }
    //! The head for `key`, inserted as no_vertex if absent. At most `expected` keys are inserted,
    //! so the table is never more than half full.
    uint32_t& slot(const CellKey& key)
    {
        for (size_t i = CellHash{}(key) & (keys_.size() - 1);; i = (i + 1) & (keys_.size() - 1))
        {
            if (values_[i] == no_vertex)
            {
                keys_[i] = key;
                return values_[i];
            }
            if (keys_[i] == key)
                return values_[i];
        }
    }

private:
    std::vector<CellKey> keys_;
    std::vector<uint32_t> values_;
};

// Exact duplicates: the bit patterns of the coordinates are the key (+0 and -0 made equal).
std::vector<uint32_t> weld_exact(const std::vector<Vec3>& positions, const std::vector<bool>& skip)
{
    std::vector<uint32_t> target(positions.size());
    CellTable first(positions.size());
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
        uint32_t& earlier = first.slot(CellKey{bits[0], bits[1], bits[2]});
        if (earlier == no_vertex)
            earlier = static_cast<uint32_t>(i);
        else
            target[i] = earlier;
    }
    return target;
}

} // namespace

std::vector<uint32_t> weld_vertices(const std::vector<Vec3>& positions, double tolerance, const std::vector<bool>& skip)
{
    if (!(tolerance > 0))
        return weld_exact(positions, skip);

    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < positions.size(); ++i)
        if (!skip[i])
            lo = lo.cwiseMin(positions[i]);

    // Cells four tolerances wide: a partner within the tolerance is in the vertex's own cell or,
    // only on the axes where the vertex is within one tolerance of its cell's side, in the
    // neighbouring cell there. That is 3.4 cells on average instead of 27. Each cell keeps a linked
    // list (head in the table, links in `next`) of the kept vertices in it.
    const double cell = 4 * tolerance;
    const double max_cell = 4e18;
    std::vector<uint32_t> target(positions.size());
    std::vector<uint32_t> next(positions.size(), no_vertex);
    CellTable head(positions.size());
    const double tol2 = tolerance * tolerance;
    for (size_t i = 0; i < positions.size(); ++i)
    {
        target[i] = static_cast<uint32_t>(i);
        if (skip[i])
            continue;
        const Vec3& p = positions[i];
        int64_t c[3];
        int lo_side[3], hi_side[3];
        for (int a = 0; a < 3; ++a)
        {
            const double u = std::min((p[a] - lo[a]) / cell, max_cell);
            const double f = std::floor(u);
            c[a] = static_cast<int64_t>(f);
            lo_side[a] = u - f < 0.25 ? -1 : 0; // 0.25 = tolerance / cell
            hi_side[a] = u - f > 0.75 ? 1 : 0;
        }
        uint32_t found = no_vertex;
        for (int dx = lo_side[0]; dx <= hi_side[0]; ++dx)
            for (int dy = lo_side[1]; dy <= hi_side[1]; ++dy)
                for (int dz = lo_side[2]; dz <= hi_side[2]; ++dz)
                    for (uint32_t j = head.find(CellKey{c[0] + dx, c[1] + dy, c[2] + dz}); j != no_vertex; j = next[j])
                        if ((positions[j] - p).squaredNorm() <= tol2 && j < found)
                            found = j;
        if (found != no_vertex)
        {
            target[i] = found;
            continue;
        }
        uint32_t& first = head.slot(CellKey{c[0], c[1], c[2]});
        next[i] = first;
        first = static_cast<uint32_t>(i);
    }
    return target;
}

} // namespace zomeify
