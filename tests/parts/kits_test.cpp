#include "core/parts/kits.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.h"
#include "core/io/model_io.h"
#include "core/io/vef.h"
#include "core/parts/parts_report.h"
#include "tests/support/paths.h"

using namespace zomeify;

namespace {

PartsList needs(size_t b0, size_t balls)
{
    PartsList p;
    p.struts[static_cast<size_t>(StrutKind::B0)] = b0;
    p.strut_count = b0;
    p.balls = balls;
    return p;
}

std::string plan_string(const KitPlan& plan)
{
    std::string s;
    for (const auto& [kit, n] : plan.kits)
        s += std::to_string(n) + "x" + std::string(kit->id) + " ";
    return s;
}

// Brute force over every combination up to generous bounds: the fewest parts, then fewest kits.
std::pair<size_t, size_t> brute_force(const PartsList& parts)
{
    const auto& kits = standard_kits();
    const PartCounts need = part_counts(parts);
    std::pair<size_t, size_t> best{SIZE_MAX, SIZE_MAX};
    for (size_t w = 0; w <= 2; ++w)
        for (size_t c3 = 0; c3 <= 12; ++c3)
            for (size_t c1 = 0; c1 <= 16; ++c1)
                for (size_t b = 0; b <= 30; ++b)
                {
                    const PartCounts have =
                        kit_contents({{&kits[0], w}, {&kits[1], c3}, {&kits[2], c1}, {&kits[3], b}});
                    bool covers = true;
                    for (size_t k = 0; k < need.size(); ++k)
                        covers &= have[k] >= need[k];
                    if (!covers)
                        continue;
                    const size_t parts_bought = w * kits[0].part_count() + c3 * kits[1].part_count() +
                                                c1 * kits[2].part_count() + b * kits[3].part_count();
                    best = std::min(best, std::pair{parts_bought, w + c3 + c1 + b});
                }
    return best;
}

} // namespace

TEST(KitPlan, FitsInOneCreator1)
{
    // The sample icosahedron: 30 B0 and 12 balls (more blue than a Basic kit has).
    const PartsList parts = parts_list(read_model_file(test::test_data_path("samples/icosahedron.zome.json")));
    const KitPlan plan = plan_kits(parts);
    EXPECT_EQ(plan_string(plan), "1xcreator1 ");
    EXPECT_EQ(plan.parts_bought, 246u);
    EXPECT_EQ(plan.spare[static_cast<size_t>(StrutKind::B0)], 0u);
    EXPECT_EQ(plan.spare[kStrutKindCount], 48u);
}

TEST(KitPlan, NeedsTwoCreator1)
{
    // 50 blue struts of one length: more than Creator 1 + Basic (45).
    const KitPlan plan = plan_kits(needs(50, 40));
    EXPECT_EQ(plan_string(plan), "2xcreator1 ");
    EXPECT_EQ(plan.parts_bought, 492u);
    // Small needs: one Basic.
    EXPECT_EQ(plan_string(plan_kits(needs(12, 20))), "1xbasic ");
    EXPECT_EQ(plan_string(plan_kits(needs(0, 0))), "");
}

TEST(KitPlan, ThePapersBunnyIsOptimal)
{
    ZOME_REQUIRE_SHARED();
    const PartsList parts = parts_list(read_vef_file(test::shared_path("data/vef/bunny.vef")));
    const KitPlan plan = plan_kits(parts);
    EXPECT_EQ(plan_string(plan), "4xcreator3 1xcreator1 ");
    EXPECT_EQ(plan.parts_bought, 3198u);
    const auto best = brute_force(parts);
    EXPECT_EQ(plan.parts_bought, best.first);
    size_t kits = 0;
    for (const auto& [kit, n] : plan.kits)
        kits += n;
    EXPECT_EQ(kits, best.second);
    for (int trial = 0; trial < 40; ++trial)
    {
        PartsList p;
        for (int k = 0; k < kStrutKindCount; ++k)
            p.struts[static_cast<size_t>(k)] = static_cast<size_t>((trial * 37 + k * 101) % (60 + trial * 9));
        p.balls = static_cast<size_t>((trial * 53) % 400);
        EXPECT_EQ(plan_kits(p).parts_bought, brute_force(p).first) << "trial " << trial;
    }
}

TEST(KitPlan, MissingWithOwnedKits)
{
    ZOME_REQUIRE_SHARED();
    const PartsList parts = parts_list(read_vef_file(test::shared_path("data/vef/bunny.vef")));
    const OwnedKits owned = parse_owned_kits("creator3, 2 x Creator 1");
    ASSERT_EQ(owned.size(), 2u);
    EXPECT_EQ(owned[1].second, 2u);
    const PartCounts missing = missing_parts(parts, owned);
    EXPECT_EQ(missing[static_cast<size_t>(StrutKind::B0)], 179u - 150u);
    EXPECT_EQ(missing[static_cast<size_t>(StrutKind::B2)], 0u);
    EXPECT_EQ(missing[kStrutKindCount], 392u - 300u);
    const auto doc = nlohmann::json::parse(parts_report_json(parts, owned));
    EXPECT_EQ(doc["missing"]["Y0"], 255 - 100);
    EXPECT_EQ(doc["kit_plan"]["parts_bought"], 3198);
    EXPECT_THROW(parse_owned_kits("creator9"), InvalidInputError);
    EXPECT_THROW(parse_owned_kits("0 x basic"), InvalidInputError);
}
