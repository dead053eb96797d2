// The (26, 6) simple-voxel test on hand-made neighbourhoods, and its agreement with the Euler
// characteristic on random ones (a simple flip never changes it).

#include <random>

#include <gtest/gtest.h>

#include "core/voxel/simple_voxel.h"

using namespace zomeify;

namespace {

constexpr int bit(int dx, int dy, int dz) { return (dx + 1) + 3 * (dy + 1) + 9 * (dz + 1); }

Neighbourhood with(std::initializer_list<std::array<int, 3>> cells)
{
    Neighbourhood n = 0;
    for (const auto& c : cells)
        n |= 1u << bit(c[0], c[1], c[2]);
    return n;
}

// Euler characteristic of the union of the closed unit cubes of a 3×3×3 set: count the distinct
// vertices, edges, faces and cubes of the cubical complex (on a doubled grid, an element is a
// point whose odd coordinates mark the directions it spans).
long long euler(Neighbourhood n)
{
    std::vector<uint8_t> used(7 * 7 * 7, 0);
    for (int b = 0; b < 27; ++b)
    {
        if (!(n >> b & 1))
            continue;
        const int x = 2 * (b % 3) + 1, y = 2 * (b / 3 % 3) + 1, z = 2 * (b / 9) + 1;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    used[((z + dz) * 7 + (y + dy)) * 7 + (x + dx)] = 1;
    }
    long long chi = 0;
    for (int z = 0; z < 7; ++z)
        for (int y = 0; y < 7; ++y)
            for (int x = 0; x < 7; ++x)
                if (used[(z * 7 + y) * 7 + x])
                    chi += ((x % 2) + (y % 2) + (z % 2)) % 2 ? -1 : 1;
    return chi;
}

} // namespace

TEST(VoxelSimple, HandMadeNeighbourhoods)
{
    // An isolated voxel is a whole component: not simple.
    EXPECT_FALSE(is_simple(0));
    // A voxel buried in a solid: removing it opens a cavity.
    EXPECT_FALSE(is_simple(0x7FFFFFF & ~(1u << 13)));
    // A tip on a face, an edge or a corner of the rest: simple.
    EXPECT_TRUE(is_simple(with({{-1, 0, 0}})));
    EXPECT_TRUE(is_simple(with({{-1, -1, 0}})));
    EXPECT_TRUE(is_simple(with({{-1, -1, -1}})));
    // A bridge between two parts: not simple (T26 = 2).
    EXPECT_EQ(object_components(with({{-1, 0, 0}, {1, 0, 0}})), 2);
    EXPECT_FALSE(is_simple(with({{-1, 0, 0}, {1, 0, 0}})));
    // In the middle of a flat slab, which separates the background above from below (T6 = 2):
    // removing it would punch a tunnel, so not simple.
    Neighbourhood slab = 0;
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            slab |= 1u << bit(dx, dy, 0);
    EXPECT_EQ(background_components(slab), 2);
    EXPECT_FALSE(is_simple(slab));
    // On the face of a solid half-space: simple.
    Neighbourhood half = 0;
    for (int b = 0; b < 27; ++b)
        if (b / 9 == 0 || (b / 9 == 1 && b != 13))
            half |= 1u << b;
    EXPECT_TRUE(is_simple(half & ~(1u << bit(0, 0, 0))));
}

TEST(VoxelSimple, SimpleFlipsKeepTheEulerCharacteristic)
{
    std::mt19937 rng(11);
    int simple = 0;
    for (int n = 0; n < 20000; ++n)
    {
        const Neighbourhood nb = rng() & 0x7FFFFFF & ~(1u << 13);
        if (!is_simple(nb))
            continue;
        ++simple;
        EXPECT_EQ(euler(nb), euler(nb | 1u << 13)) << std::hex << nb;
    }
    EXPECT_GT(simple, 100);
}
