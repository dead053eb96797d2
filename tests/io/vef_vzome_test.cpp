// VEF as vZome itself writes it (versions 6 to 10: offset, dimension, actual, scale, scale
// vector, fractions, other golden field names), fixtures in tests/data/vef/ written the way
// vZome's VefVectorExporter and VefParser spell each feature; and the writer's --no-faces.
#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/io/model_io.h"
#include "core/io/vef.h"
#include "core/io/vef_number.h"
#include "core/zome/slots.h"
#include "tests/support/model_compare.h"
#include "tests/support/paths.h"

using namespace zomeify;

namespace {

// The icosahedron of 30 B0 struts with its centre ball and 12 R0 struts, as every fixture holds it.
void expect_centred_icosahedron(const ZomeModel& m)
{
    ASSERT_EQ(m.nodes.size(), 13u);
    ASSERT_EQ(m.struts.size(), 42u);
    size_t blue = 0, red = 0;
    for (const auto& s : m.struts)
    {
        const StrutKind k = vector_kind(vector_id_of(m.nodes[s[1]] - m.nodes[s[0]]));
        blue += k == StrutKind::B0;
        red += k == StrutKind::R0;
    }
    EXPECT_EQ(blue, 30u);
    EXPECT_EQ(red, 12u);
}

std::string vef_error(const std::string& text)
{
    try
    {
        read_vef(text);
    }
    catch (const InvalidInputError& e)
    {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos);
        EXPECT_EQ(msg.rfind("not a valid VEF file", 0), 0u) << msg;
        return msg;
    }
    ADD_FAILURE() << "no error for " << text.substr(0, 80);
    return {};
}

} // namespace

TEST(VefVzome, Version10CopyWithOffsetMovesTheModel)
{
    VefReadInfo info;
    const ZomeModel m = read_vef_file(test::test_data_path("vef/vzome10_copy.vef"), &info);
    EXPECT_EQ(info.version, 10);
    EXPECT_EQ(info.phi_power, 2);
    EXPECT_EQ(info.balls, 13u);
    expect_centred_icosahedron(m);
    EXPECT_EQ(m.faces.size(), 20u);
    // The offset is minus vertex 4, so vertex 4 lands on the origin.
    EXPECT_TRUE(m.nodes[4].is_zero());
}

TEST(VefVzome, Version9DimensionActualAndScale)
{
    VefReadInfo info;
    const ZomeModel m = read_vef_file(test::test_data_path("vef/vzome9_dimension_scale.vef"), &info);
    EXPECT_EQ(info.version, 9);
    EXPECT_EQ(info.phi_power, 2);
    expect_centred_icosahedron(m);
    EXPECT_TRUE(m.faces.empty());
}

TEST(VefVzome, Version8ScaleVectorAndFractions)
{
    const ZomeModel m = read_vef_file(test::test_data_path("vef/vzome8_scale_vector_fractions.vef"));
    expect_centred_icosahedron(m);
    // The same positions as the plain fixture (without its offset).
    const ZomeModel plain = read_vef_file(test::test_data_path("vef/vzome9_dimension_scale.vef"));
    EXPECT_EQ(test::canonical(m), test::canonical(plain));
}

TEST(VefVzome, SnubDodecahedronFieldWithZeroExtraFactors)
{
    const ZomeModel m = read_vef_file(test::test_data_path("vef/vzome6_snub_field.vef"));
    expect_centred_icosahedron(m);
    EXPECT_EQ(test::canonical(m),
              test::canonical(read_vef_file(test::test_data_path("vef/vzome9_dimension_scale.vef"))));
}

TEST(VefVzome, RoundTripThroughZomeJsonAndBack)
{
    // vZome VEF 10 → .zome.json → VEF → the same model.
    const ZomeModel original = read_vef_file(test::test_data_path("vef/vzome10_copy.vef"));
    const std::string json_path = test::temp_path("vzome10_copy.zome.json");
    write_model_file(json_path, original);
    const ZomeModel from_json = read_model_file(json_path);
    const std::string vef_path = test::temp_path("vzome10_copy_again.vef");
    write_model_file(vef_path, from_json);
    const ZomeModel back = read_model_file(vef_path);
    EXPECT_EQ(test::canonical(back), test::canonical(original));
    EXPECT_EQ(back.faces.size(), 20u);
}

TEST(VefVzome, NumbersAsVzomeWritesThem)
{
    auto n = [](const char* t) { return parse_vef_number(t, false, "test"); };
    EXPECT_EQ(n("(8/2,4/2)"), (GoldenFraction{QPhi{2, 4}, 1})); // 4φ + 2
    EXPECT_EQ(n("(1/2,3)"), (GoldenFraction{QPhi{6, 1}, 2}));   // (φ + 6)/2
    EXPECT_EQ(n("-3/6"), (GoldenFraction{QPhi{-1, 0}, 2}));
    EXPECT_EQ(n("(5)"), (GoldenFraction{QPhi{5, 0}, 1}));
    EXPECT_EQ(n("(0,0,0,0,4,2)"), (GoldenFraction{QPhi{2, 4}, 1}));
    EXPECT_THROW(parse_vef_number("(1,2)", true, "test"), InvalidInputError);
    EXPECT_THROW(n("(1,0,4,2)"), InvalidInputError);
    EXPECT_THROW(n("(1/0,2)"), InvalidInputError);
    EXPECT_THROW(n("(a,2)"), InvalidInputError);
}

TEST(VefVzome, RationalFieldReadsWithoutParentheses)
{
    // Two B0 struts along x at φ-power 0 (b0 = 2 raw units), rational coordinates.
    const ZomeModel m = read_vef("vZome VEF 7 field rational actual scale 2 3 0 0 0 0 0 1 0 0 0 2 0 0 2 0 1 1 2");
    ASSERT_EQ(m.struts.size(), 2u);
    EXPECT_NE(vef_error("vZome VEF 7 field rational 1 (0,0) (1,0) 0 0 0").find("irrational"), std::string::npos);
}

TEST(VefVzome, GarbageStillHasClearMessages)
{
    EXPECT_NE(vef_error("vZome VEF 10 field rootTwo 0 0").find("golden field"), std::string::npos);
    EXPECT_NE(vef_error("vZome VEF 9 field golden dimension 5 0").find("dimension 5"), std::string::npos);
    EXPECT_NE(vef_error("vZome VEF 10 field golden offset (0,0) (1,0)").find("ends early"), std::string::npos);
    EXPECT_NE(vef_error("vZome VEF 8 field golden scale 1/0 0").find("divides by zero"), std::string::npos);
    EXPECT_NE(vef_error("vZome VEF 6 field golden 2 (0,0) (0,0) (0,0) (0,0) (0,0) (1/3,0) (0,0) (0,0) 1 0 1")
                  .find("not a Zome strut"),
              std::string::npos);
    EXPECT_NE(vef_error("vZome VEF 6 field golden 1 (0,0) (99999999999999999,0) (0,0) (0,0) 0 0 1 0").find("too large"),
              std::string::npos);
}

TEST(VefVzome, OffTheLatticeOffsetMovesByVertexZero)
{
    VefReadInfo info;
    const ZomeModel m = read_vef(
        "vZome VEF 10 field golden offset 0 1/3 0 0 2 (0,0) (0,0) (0,0) (0,0) (0,0) (4,2) (0,0) (0,0) 1 0 1", &info);
    EXPECT_TRUE(info.moved);
    EXPECT_TRUE(m.nodes[0].is_zero());
    EXPECT_EQ(vector_kind(vector_id_of(m.nodes[1] - m.nodes[0])), StrutKind::B1);
}

TEST(VefVzome, WriterCanLeaveFacesOut)
{
    const ZomeModel m = read_vef_file(test::test_data_path("vef/vzome10_copy.vef"));
    const std::string without = write_vef(m, VefWriteOptions{false});
    const ZomeModel back = read_vef(without);
    EXPECT_TRUE(back.faces.empty());
    EXPECT_EQ(back.struts.size(), 42u);
    EXPECT_EQ(write_model_buffer(m, "x.vef", WriteOptions{ObjUnits::Millimetres, false}), without);
    EXPECT_EQ(read_vef(write_vef(m)).faces.size(), 20u);
}
