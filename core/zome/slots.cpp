#include "core/zome/slots.h"

#include <cmath>
#include <vector>

#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

// Twice a coordinate, as the pair (φ-coefficient, integer) of the 6-integer form.
struct Half
{
    int32_t phi, one;
};
constexpr Half kZero{0, 0}, kOne{0, 2}, kHalf{0, 1}, kHalfPhi{1, 0}, kHalfInvPhi{1, -1};

Half neg(Half h) { return {-h.phi, -h.one}; }

ZVec make(Half x, Half y, Half z) { return ZVec{{x.phi, x.one, y.phi, y.one, z.phi, z.one}}; }

// All sign choices of the non-zero entries of (x, y, z), then the three cyclic permutations.
void add_cyclic_signed(std::vector<ZVec>& out, Half x, Half y, Half z)
{
    const Half base[3] = {x, y, z};
    for (int rot = 0; rot < 3; ++rot)
        for (int signs = 0; signs < 8; ++signs)
        {
            Half h[3];
            bool redundant = false;
            for (int k = 0; k < 3; ++k)
            {
                const Half b = base[(k + rot) % 3];
                const bool flip = (signs >> k) & 1;
                const bool zero = b.phi == 0 && b.one == 0;
                redundant |= zero && flip; // -0 is 0: skip duplicate sign patterns
                h[k] = flip ? neg(b) : b;
            }
            if (!redundant)
                out.push_back(make(h[0], h[1], h[2]));
        }
}

// Adds each vector followed by its opposite, so that slot 2k and 2k+1 are opposite.
void add_with_opposites(std::vector<ZVec>& slots, const std::vector<ZVec>& candidates)
{
    for (const ZVec& v : candidates)
    {
        bool seen = false;
        for (const ZVec& s : slots)
            seen |= (s == v);
        if (!seen)
        {
            slots.push_back(v);
            slots.push_back(-v);
        }
    }
}

std::vector<ZVec> unit_slots()
{
    std::vector<ZVec> slots;
    std::vector<ZVec> blue, yellow, red;
    // Blue: (±1,0,0) and permutations; cyclic permutations of (±φ, ±1/φ, ±1)/2.
    add_cyclic_signed(blue, kOne, kZero, kZero);
    add_cyclic_signed(blue, kHalfPhi, kHalfInvPhi, kHalf);
    // Yellow: (±1,±1,±1)/2; cyclic permutations of (0, ±1/φ, ±φ)/2.
    add_cyclic_signed(yellow, kHalf, kHalf, kHalf);
    add_cyclic_signed(yellow, kZero, kHalfInvPhi, kHalfPhi);
    // Red: cyclic permutations of (0, ±φ, ±1)/2.
    add_cyclic_signed(red, kZero, kHalfPhi, kHalf);
    add_with_opposites(slots, blue);
    add_with_opposites(slots, yellow);
    add_with_opposites(slots, red);
    return slots;
}

// Open-addressing table from the 186 vectors to their ids; built once.
struct VectorIndex
{
    static constexpr size_t kBuckets = 1024; // load < 0.2: nearly always one probe
    std::array<ZVec, kVectorCount> vectors{};
    std::array<int16_t, kBuckets> bucket{};

    VectorIndex()
    {
        const std::vector<ZVec> slots = unit_slots();
        for (int s = 0; s < kSlotCount; ++s)
        {
            ZVec v = slots[static_cast<size_t>(s)];
            for (int size = 0; size < kSizeCount; ++size, v = v.times_phi())
                vectors[static_cast<size_t>(vector_id(s, size))] = v;
        }
        bucket.fill(-1);
        for (int id = 0; id < kVectorCount; ++id)
        {
            size_t b = ZVecHash{}(vectors[static_cast<size_t>(id)]) & (kBuckets - 1);
            while (bucket[b] >= 0)
                b = (b + 1) & (kBuckets - 1);
            bucket[b] = static_cast<int16_t>(id);
        }
    }

    int find(const ZVec& v) const noexcept
    {
        for (size_t b = ZVecHash{}(v) & (kBuckets - 1);; b = (b + 1) & (kBuckets - 1))
        {
            const int id = bucket[b];
            if (id < 0)
                return -1;
            if (vectors[static_cast<size_t>(id)] == v)
                return id;
        }
    }
};

// Built once; an allocation failure there ends the program (noexcept), never a lookup.
const VectorIndex& vector_index() noexcept
{
    static const VectorIndex index;
    return index;
}

StrutKindInfo make_info(StrutKind k)
{
    static constexpr std::string_view kNames[] = {"B0", "B1", "B2", "Y0", "Y1", "Y2", "R0", "R1", "R2"};
    static constexpr std::string_view kCodes[] = {"PST-B0-BLU", "PST-B1-BLU", "PST-B2-BLU", "PST-Y0-YEL", "PST-Y1-YEL",
                                                  "PST-Y2-YEL", "PST-R0-RED", "PST-R1-RED", "PST-R2-RED"};
    // 4·length² of the size-0 strut: blue 4 (length 1), yellow 3 (√3/2), red 2 + φ (√(2+φ)/2).
    static constexpr QPhi kBase4[] = {{4, 0}, {3, 0}, {2, 1}};
    const Color color = kind_color(k);
    const int size = kind_size(k);
    const QPhi length4 = kBase4[static_cast<int>(color)] * phi_power(2 * size);
    const double length = 0.5 * std::sqrt(length4.to_double());
    const auto i = static_cast<size_t>(k);
    return {k, kNames[i], color_name(color), kCodes[i], length4, length, length * kMmPerB0};
}

} // namespace

std::string_view color_name(Color c)
{
    switch (c)
    {
    case Color::Blue:
        return "blue";
    case Color::Yellow:
        return "yellow";
    case Color::Red:
        return "red";
    }
    return "?";
}

const StrutKindInfo& kind_info(StrutKind k)
{
    static const std::array<StrutKindInfo, kStrutKindCount> infos = [] {
        std::array<StrutKindInfo, kStrutKindCount> a{};
        for (int i = 0; i < kStrutKindCount; ++i)
            a[static_cast<size_t>(i)] = make_info(static_cast<StrutKind>(i));
        return a;
    }();
    return infos[static_cast<size_t>(k)];
}

const ZVec& zome_vector(int id) noexcept { return vector_index().vectors[static_cast<size_t>(id)]; }

const std::array<ZVec, kVectorCount>& zome_vectors() noexcept { return vector_index().vectors; }

int vector_id_of(const ZVec& v) noexcept { return vector_index().find(v); }

} // namespace zomeify
