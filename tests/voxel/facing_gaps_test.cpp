// facing_gaps (facing_gaps.h): the width of the gap in front of S where another part faces back, and
// the automatic choice's use of it (a knot whose strands nearly touch gets a grid that keeps them apart).

#include <gtest/gtest.h>

#include "core/pipeline/z0_choice.h"
#include "core/voxel/facing_gaps.h"
#include "tests/support/geom_fixtures.h"
#include "tests/voxel/voxel_test_support.h"

using namespace zomeify;
using namespace zomeify::voxel_test;

TEST(FacingGaps, TwoCubesFaceEachOtherAcrossTheirGapOnly)
{
    // Two unit cubes 0.3 apart along x: of the 12 faces of equal area, the two facing ones see the gap.
    TriangleMesh a = test::make_cube(0.5, 4), b = test::make_cube(0.5, 4);
    for (Vec3& p : a.positions)
        p.x() -= 0.65;
    for (Vec3& p : b.positions)
        p.x() += 0.65;
    const auto offset = static_cast<uint32_t>(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (const auto& t : b.triangles)
        a.triangles.push_back({{t[0] + offset, t[1] + offset, t[2] + offset}});
    const SurfaceProjector projector(a);
    const FacingGaps gaps = facing_gaps(projector, 1.0, 6000);
    ASSERT_EQ(gaps.widths.size(), 6000u);
    for (double w : gaps.widths)
    {
        if (w >= 0.0)
        {
            EXPECT_NEAR(w, 0.3, 0.05);
        }
    }
    EXPECT_NEAR(gaps.fraction_narrower_than(0.35), 2.0 / 12.0, 0.02);
    EXPECT_EQ(gaps.fraction_narrower_than(0.25), 0.0);
}

TEST(FacingGaps, AConvexShapeFacesNothing)
{
    const SurfaceProjector projector(test::make_icosphere(1.0, 3));
    EXPECT_EQ(facing_gaps(projector, 2.0, 1000).fraction_narrower_than(2.0), 0.0);
    // No width to look across, or no samples: nothing measured, nothing narrow.
    EXPECT_TRUE(facing_gaps(projector, 0.0).widths.empty());
    EXPECT_TRUE(facing_gaps(projector, 2.0, 0).widths.empty());
    EXPECT_EQ(facing_gaps(projector, 0.0).fraction_narrower_than(1.0), 0.0);
}

TEST(FacingGaps, AKnotWhoseStrandsNearlyTouchGetsAFinerGrid)
{
#ifdef ZOME_SANITIZED
    GTEST_SKIP() << "a choice, not a memory check: the same code runs in AutoResolution.* there";
#endif
    // At the default 8 cells 11% of the trefoil faces another strand closer than a cell, and its Z0,
    // though of genus 1, is a lump; from 11 cells no more than 5% does, and 12 keeps the genus.
    const LoadedSurface& s = generated_surface("trefoil");
    const AutoResolution a = automatic_resolution(*s.projector, s.genus, s.predicate());
    EXPECT_GT(a.narrow_at_preferred, 0.05);
    EXPECT_GT(a.gap_resolution, a.preferred);
    EXPECT_GE(a.resolution, a.gap_resolution);
    EXPECT_TRUE(a.genus_kept) << a.message;
    EXPECT_NE(a.message.find("gaps narrower than a cell"), std::string::npos) << a.message;
}
