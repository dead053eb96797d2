#include "core/parts/parts_list.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/io/vef.h"
#include "tests/support/paths.h"

using namespace zomeify;

TEST(PartsList, ThePapersBunny)
{
    ZOME_REQUIRE_SHARED();
    const PartsList parts = parts_list(read_vef_file(test::shared_path("data/vef/bunny.vef")));
    EXPECT_EQ(parts.balls, 392u);
    const size_t expected[] = {179, 158, 5, 255, 119, 18, 149, 78, 7};
    for (int k = 0; k < kStrutKindCount; ++k)
        EXPECT_EQ(parts.struts[static_cast<size_t>(k)], expected[k]) << kind_info(static_cast<StrutKind>(k)).name;
    EXPECT_EQ(parts.strut_count, 968u);
    EXPECT_NEAR(parts.total_length_b0, 1155.3, 0.05); // design.md §6
    EXPECT_NEAR(parts.total_length_mm / 1000.0, 53.5, 0.05);

    const auto doc = nlohmann::json::parse(parts_json(parts));
    EXPECT_EQ(doc["balls"], 392);
    EXPECT_EQ(doc["struts"]["B0"], 179);
    EXPECT_EQ(doc["struts"]["R2"], 7);
    EXPECT_EQ(doc["kinds"].size(), 9u);

    const std::string csv = parts_csv(parts);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 11); // header, ball, 9 strut kinds
    EXPECT_NE(csv.find("PST-Y0-YEL,Y0,yellow,40.07,255"), std::string::npos);
    EXPECT_NE(parts_table(parts).find("968 struts"), std::string::npos);
}

TEST(PartsList, PhysicalSizeOfOneStrut)
{
    ZomeModel one;
    one.nodes = {ZVec{}, ZVec{{2, 0, 0, 0, 0, 0}}};
    one.struts = {{0, 1}};
    const PartsList parts = parts_list(one);
    EXPECT_NEAR(parts.size_cm[0], (74.86 + 17.673) / 10, 0.01); // B1 centre to centre plus a ball
    EXPECT_NEAR(parts.size_cm[1], 1.7673, 1e-9);
    EXPECT_NEAR(parts.total_length_mm, 74.86, 0.01);
}
