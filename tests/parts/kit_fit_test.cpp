// The kit-fit arithmetic (core/parts/kit_fit.h): the ball budget of a set of kits, the fit test on
// every part kind, and the budget after a result that missed.
#include "core/parts/kit_fit.h"

#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/parts/parts_report.h"

using namespace zomeify;

namespace {

PartCounts creator3() { return kit_contents(parse_owned_kits("creator3")); }

} // namespace

TEST(KitFit, FitsComparesEveryKindAndTheBalls)
{
    PartCounts have = creator3(), need{};
    EXPECT_TRUE(fits(need, have));
    need = have;
    EXPECT_TRUE(fits(need, have)); // exactly what the kit holds still fits
    need[static_cast<size_t>(StrutKind::R1)] += 1;
    EXPECT_FALSE(fits(need, have));
    need = have;
    need[kStrutKindCount] += 1; // one ball too many
    EXPECT_FALSE(fits(need, have));
    EXPECT_EQ(fit_text(need, have), "missing with your kits: 1 balls");
    EXPECT_EQ(fit_text(have, have), "fits your kits");
}

TEST(KitFit, BudgetFitsTheTypicalMixWithItsMargin)
{
    const PartCounts have = creator3();
    const size_t tight = balls_that_fit(have, 0.0), kept = balls_that_fit(have);
    // A Creator 3 has 36 of each red length; the typical mix uses 0.313 R1 per ball: about 115 balls.
    EXPECT_GE(tight, 110u);
    EXPECT_LE(tight, 115u);
    EXPECT_TRUE(fits(part_counts(typical_parts(tight)), have));
    EXPECT_FALSE(fits(part_counts(typical_parts(tight + 1)), have));
    EXPECT_LT(kept, tight);
    EXPECT_NEAR(static_cast<double>(kept), tight * (1.0 - kKitFitMargin), 2.0);
    // More kits, more balls; the same kits twice hold twice as many parts.
    EXPECT_GT(balls_that_fit(kit_contents(parse_owned_kits("2x creator3"))), kept);
    EXPECT_EQ(balls_that_fit(PartCounts{}), 0u);
    EXPECT_THROW(balls_that_fit(have, -0.1), InvalidInputError);
}

TEST(KitFit, TypicalPartsScaleWithTheBalls)
{
    const PartsList p = typical_parts(100);
    EXPECT_EQ(p.balls, 100u);
    EXPECT_GE(p.strut_count, 270u); // 2.7 struts per ball, rounded up per kind
    EXPECT_LE(p.strut_count, 279u);
}

TEST(KitFit, AnnealedPartsAreTheMeasuredMedianMix)
{
    // Issue 38: the typical end of the kits named before a run, 2.34 struts per Z0 ball; B1 and Y1
    // lead (0.882 and 0.604 per ball), so 1,000 balls typically take 882 B1 and 604 Y1.
    const PartsList p = annealed_parts(1000);
    EXPECT_EQ(p.balls, 1000u);
    EXPECT_EQ(p.struts[static_cast<size_t>(StrutKind::B1)], 882u);
    EXPECT_EQ(p.struts[static_cast<size_t>(StrutKind::Y1)], 604u);
    EXPECT_EQ(p.strut_count, 2343u);
    EXPECT_EQ(annealed_parts(0).strut_count, 0u);
}

TEST(KitFit, PartsForMoreBallsScaleZ0sOwnParts)
{
    // The automatic choice asks the annealer for up to 1.8 x Z0's balls: the safe end of the kit
    // estimate is Z0's parts scaled to that many, rounded up; never fewer than Z0's own.
    PartsList z0;
    z0.balls = 200;
    z0.struts[static_cast<size_t>(StrutKind::B1)] = 401;
    z0.strut_count = 401;
    const PartsList more = parts_for_balls(z0, 360);
    EXPECT_EQ(more.balls, 360u);
    EXPECT_EQ(more.struts[static_cast<size_t>(StrutKind::B1)], 722u); // 401 x 1.8 = 721.8
    EXPECT_EQ(more.strut_count, 722u);
    EXPECT_EQ(parts_for_balls(z0, 150).balls, 200u);
    EXPECT_EQ(parts_for_balls(z0, 150).struts[static_cast<size_t>(StrutKind::B1)], 401u);
}

TEST(KitFit, ShrunkBudgetFollowsTheScarcestPart)
{
    const PartCounts have = creator3();
    PartCounts need = part_counts(typical_parts(120));
    need[static_cast<size_t>(StrutKind::R1)] = 72; // twice the kit's R1
    const size_t next = shrunk_ball_budget(need, have, 120);
    EXPECT_LE(next, 60u * 95 / 100 + 1); // half the balls, less the 5 % margin
    EXPECT_GE(next, 50u);
    // Even a near miss gives fewer balls than the result had, so a retry always shrinks.
    need = have;
    need[kStrutKindCount] += 1;
    EXPECT_LT(shrunk_ball_budget(need, have, 181), 181u);
    EXPECT_EQ(shrunk_ball_budget(need, have, 0), 0u);
}

TEST(KitFit, UnknownKitIsAClearError)
{
    try
    {
        parse_owned_kits("creator9");
        FAIL();
    }
    catch (const InvalidInputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("unknown kit 'creator9'"), std::string::npos);
    }
}
