#include "core/io/vef.h"

#include <sstream>

#include <gtest/gtest.h>

#include "core/io/file_bytes.h"
#include "core/zome/slots.h"
#include "tests/support/paths.h"

using namespace zomeify;

namespace {

std::vector<std::string> tokens(const std::string& text)
{
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string t; in >> t;)
        out.push_back(t);
    return out;
}

ZomeModel one_b1()
{
    ZomeModel m;
    m.nodes = {ZVec{}, ZVec{{2, 0, 0, 0, 0, 0}}};
    m.struts = {{0, 1}};
    return m;
}

} // namespace

TEST(Vef, ThePapersBunnyReadsWithStandardStruts)
{
    ZOME_REQUIRE_SHARED();
    VefReadInfo info;
    const ZomeModel bunny = read_vef_file(test::shared_path("data/vef/bunny.vef"), &info);
    EXPECT_EQ(info.phi_power, 3); // drawn at 2φ³ per b0, one φ step above vZome's scale
    EXPECT_EQ(info.balls, 392u);
    EXPECT_EQ(bunny.nodes.size(), 392u);
    EXPECT_EQ(bunny.struts.size(), 968u);
    EXPECT_TRUE(bunny.faces.empty());
}

TEST(Vef, DesignMinimalFileIsOneB1)
{
    const std::string minimal =
        "vZome VEF 6 field golden 2 (0,0) (0,0) (0,0) (0,0) (0,0) (4,2) (0,0) (0,0) 1 0 1 0 2 0 1";
    VefReadInfo info;
    const ZomeModel m = read_vef(minimal, &info);
    EXPECT_EQ(info.phi_power, 2);
    ASSERT_EQ(m.struts.size(), 1u);
    EXPECT_EQ(vector_kind(vector_id_of(m.nodes[1] - m.nodes[0])), StrutKind::B1);
    // The writer produces the same tokens (a b1 along +x is (4,2) at vZome's scale).
    EXPECT_EQ(tokens(write_vef(one_b1())), tokens(minimal));
}

TEST(Vef, WriteReadRoundTripIsIdentical)
{
    ZOME_REQUIRE_SHARED();
    ZomeModel bunny = read_vef_file(test::shared_path("data/vef/bunny.vef"));
    const std::string text = write_vef(bunny);
    VefReadInfo info;
    const ZomeModel back = read_vef(text, &info);
    EXPECT_EQ(info.phi_power, 2);
    EXPECT_EQ(back, bunny);
    // With faces too.
    ZomeModel square;
    square.nodes = {ZVec{}, ZVec{{2, 0, 0, 0, 0, 0}}, ZVec{{2, 0, 2, 0, 0, 0}}, ZVec{{0, 0, 2, 0, 0, 0}}};
    square.struts = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    square.faces = {{0, 1, 2, 3}};
    EXPECT_EQ(read_vef(write_vef(square)), square);
}

TEST(Vef, OtherReferenceFilesRead)
{
    ZOME_REQUIRE_SHARED();
    const ZomeModel dodeca = read_vef_file(test::shared_path("data/vef/dodecahedron.vef"));
    EXPECT_EQ(dodeca.nodes.size(), 20u);
    EXPECT_EQ(dodeca.struts.size(), 30u);
    for (const auto& s : dodeca.struts)
        EXPECT_EQ(vector_kind(vector_id_of(dodeca.nodes[s[1]] - dodeca.nodes[s[0]])), StrutKind::B1);
    const ZomeModel dome = read_vef_file(test::shared_path("data/vef/dome.vef"));
    EXPECT_EQ(dome.nodes.size(), 954u);
    EXPECT_EQ(dome.struts.size(), 1790u);
}
