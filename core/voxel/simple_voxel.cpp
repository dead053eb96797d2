#include "core/voxel/simple_voxel.h"

#include <array>
#include <cstdlib>

namespace zomeify {

namespace {

constexpr int kCentre = 13;

struct AdjacencyTables
{
    std::array<uint32_t, 27> adj26{}; // neighbours sharing a face, edge or corner (centre excluded)
    std::array<uint32_t, 27> adj6{};  // neighbours sharing a face (centre excluded)
    uint32_t n26 = 0;                 // the 26 cells around the centre
    uint32_t n18 = 0;                 // the 18 face and edge neighbours of the centre
    uint32_t n6 = 0;                  // the 6 face neighbours of the centre
};

int offset(int bit, int axis) { return (axis == 0 ? bit % 3 : axis == 1 ? (bit / 3) % 3 : bit / 9) - 1; }

AdjacencyTables make_tables()
{
    AdjacencyTables t;
    for (int p = 0; p < 27; ++p)
    {
        if (p == kCentre)
            continue;
        int far = 0;
        for (int a = 0; a < 3; ++a)
            far += std::abs(offset(p, a));
        t.n26 |= 1u << p;
        if (far <= 2)
            t.n18 |= 1u << p;
        if (far == 1)
            t.n6 |= 1u << p;
        for (int q = 0; q < 27; ++q)
        {
            if (q == kCentre || q == p)
                continue;
            int dmax = 0, dsum = 0;
            for (int a = 0; a < 3; ++a)
            {
                const int d = std::abs(offset(p, a) - offset(q, a));
                dmax = d > dmax ? d : dmax;
                dsum += d;
            }
            if (dmax == 1)
                t.adj26[p] |= 1u << q;
            if (dmax == 1 && dsum == 1)
                t.adj6[p] |= 1u << q;
        }
    }
    return t;
}

const AdjacencyTables& tables()
{
    static const AdjacencyTables t = make_tables();
    return t;
}

// Grows the component of `seed` inside `set` along `adj`; returns its cells.
uint32_t flood(uint32_t seed, uint32_t set, const std::array<uint32_t, 27>& adj)
{
    uint32_t comp = seed, frontier = seed;
    while (frontier)
    {
        uint32_t next = 0;
        for (uint32_t f = frontier; f; f &= f - 1)
            next |= adj[__builtin_ctz(f)];
        next &= set & ~comp;
        comp |= next;
        frontier = next;
    }
    return comp;
}

} // namespace

Neighbourhood neighbourhood(const VoxelGrid& grid, int i, int j, int k)
{
    Neighbourhood n = 0;
    int bit = 0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx, ++bit)
                if (grid.occupied(i + dx, j + dy, k + dz))
                    n |= 1u << bit;
    return n;
}

int object_components(Neighbourhood n)
{
    const auto& t = tables();
    uint32_t rest = n & t.n26;
    int count = 0;
    while (rest)
    {
        rest &= ~flood(rest & (~rest + 1), rest, t.adj26);
        ++count;
    }
    return count;
}

int background_components(Neighbourhood n)
{
    const auto& t = tables();
    const uint32_t background = ~n & t.n18;
    uint32_t seeds = background & t.n6;
    int count = 0;
    while (seeds)
    {
        seeds &= ~flood(seeds & (~seeds + 1), background, t.adj6);
        ++count;
    }
    return count;
}

bool is_simple(Neighbourhood n) { return object_components(n) == 1 && background_components(n) == 1; }

} // namespace zomeify
