#include "core/zome/slots.h"

#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "core/zome/real_sizes.h"
#include "core/zome/symmetry.h"

using namespace zomeify;

TEST(Slots, SixtyTwoSlotsOneHundredEightySixVectors)
{
    int per_color[3] = {0, 0, 0};
    for (int s = 0; s < kSlotCount; ++s)
        ++per_color[static_cast<int>(slot_color(s))];
    EXPECT_EQ(per_color[0], 30);
    EXPECT_EQ(per_color[1], 20);
    EXPECT_EQ(per_color[2], 12);

    std::set<ZVec> distinct(zome_vectors().begin(), zome_vectors().end());
    EXPECT_EQ(distinct.size(), 186u);
    for (int id = 0; id < kVectorCount; ++id)
    {
        EXPECT_EQ(vector_id_of(zome_vector(id)), id);
        const int s = vector_slot(id);
        EXPECT_EQ(zome_vector(vector_id(opposite_slot(s), vector_size(id))), -zome_vector(id));
    }
}

TEST(Slots, NonZomeVectorsAreRejected)
{
    EXPECT_EQ(vector_id_of(ZVec{}), -1);
    EXPECT_EQ(vector_id_of(ZVec{{0, 1, 0, 0, 0, 0}}), -1);                           // half a b0
    EXPECT_EQ(vector_id_of(zome_vector(0).times_phi().times_phi().times_phi()), -1); // b3
    EXPECT_EQ(vector_id_of(zome_vector(0).div_phi()), -1);                           // b(-1)
    EXPECT_EQ(vector_id_of(zome_vector(0) + zome_vector(vector_id(2, 0))), -1);      // x + z, length √2
    EXPECT_EQ(slot_of(ZVec{{0, 1, 0, 1, 0, 1}}), 30);                                // (1,1,1)/2 is yellow
}

TEST(Slots, DirectionsHaveTheRightColour)
{
    // Blue axes are 2-fold, yellow 3-fold, red 5-fold: count the rotations fixing each slot.
    const auto& rotations = zome_rotations();
    for (int s = 0; s < kSlotCount; ++s)
    {
        int fixing = 0;
        for (const Rotation& r : rotations)
            fixing += r.slot_map[static_cast<size_t>(s)] == s;
        const int expected = slot_color(s) == Color::Blue ? 2 : slot_color(s) == Color::Yellow ? 3 : 5;
        EXPECT_EQ(fixing, expected) << "slot " << s;
    }
}

TEST(Slots, RealSizesMatchVzome)
{
    const double expected_mm[] = {46.27, 74.86, 121.13, 40.07, 64.83, 104.90, 44.00, 71.20, 115.20};
    for (int k = 0; k < kStrutKindCount; ++k)
    {
        const StrutKindInfo& info = kind_info(static_cast<StrutKind>(k));
        EXPECT_NEAR(info.length_mm, expected_mm[k], 0.01) << info.name;
        EXPECT_NEAR(info.length * info.length * 4, info.length4.to_double(), 1e-9);
    }
    EXPECT_EQ(kind_info(StrutKind::B1).part_code, "PST-B1-BLU");
    EXPECT_EQ(kind_info(StrutKind::Y2).part_code, "PST-Y2-YEL");
    EXPECT_EQ(kind_info(StrutKind::R0).part_code, "PST-R0-RED");
}

TEST(Symmetry, ExactlySixtyRotationsPreserveTheSet)
{
    const auto& rotations = zome_rotations();
    ASSERT_EQ(rotations.size(), 60u);
    for (int s = 0; s < kSlotCount; ++s)
        EXPECT_EQ(rotations[0].slot_map[static_cast<size_t>(s)], s); // identity first
    std::set<std::array<uint8_t, kSlotCount>> distinct;
    for (const Rotation& r : rotations)
    {
        distinct.insert(r.slot_map);
        // det = +1: (c0 × c1) · c2 = 1, i.e. 4·det = 4.
        const auto c01 = cross(r.columns[0], r.columns[1]);
        ASSERT_TRUE(c01.has_value());
        EXPECT_EQ(*c01, r.columns[2]);
        // Each rotation is a bijection of the 186 vectors preserving size.
        std::set<int> images;
        for (int id = 0; id < kVectorCount; ++id)
        {
            const auto image = r.apply(zome_vector(id));
            ASSERT_TRUE(image.has_value());
            const int j = vector_id_of(*image);
            ASSERT_GE(j, 0);
            EXPECT_EQ(vector_size(j), vector_size(id));
            EXPECT_EQ(slot_color(vector_slot(j)), slot_color(vector_slot(id)));
            images.insert(j);
        }
        EXPECT_EQ(images.size(), 186u);
    }
    EXPECT_EQ(distinct.size(), 60u);
    // Closed under composition: a group.
    for (const Rotation& a : rotations)
        for (const Rotation& b : rotations)
        {
            std::array<uint8_t, kSlotCount> ab{};
            for (int s = 0; s < kSlotCount; ++s)
                ab[static_cast<size_t>(s)] = a.slot_map[b.slot_map[static_cast<size_t>(s)]];
            EXPECT_TRUE(distinct.count(ab));
        }
}

TEST(Symmetry, MirrorImageIsNotASymmetry)
{
    // vZome's handedness: reflecting x maps some red vector outside the set.
    int outside = 0;
    for (int id = 0; id < kVectorCount; ++id)
    {
        ZVec m = zome_vector(id);
        m.c[0] = -m.c[0];
        m.c[1] = -m.c[1];
        std::swap(m.c[2], m.c[4]); // x → −x combined with y ↔ z is a reflection
        std::swap(m.c[3], m.c[5]);
        outside += vector_id_of(m) < 0;
    }
    EXPECT_GT(outside, 0);
}
