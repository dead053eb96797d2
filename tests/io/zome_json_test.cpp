#include "core/io/zome_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/io/model_io.h"
#include "core/io/vef.h"
#include "tests/support/paths.h"

using namespace zomeify;

TEST(ZomeJson, RoundTripIsIdentical)
{
    ZOME_REQUIRE_SHARED();
    ZomeModel bunny = read_vef_file(test::shared_path("data/vef/bunny.vef"));
    bunny.transform.scale = 0.1179;
    bunny.transform.translation = {0.25, -1.0 / 3.0, 1e-7};
    bunny.stats_json = R"({"seconds":1.5,"threads":2})";
    const std::string text = write_zome_json(bunny);
    EXPECT_EQ(read_zome_json(text), bunny);

    ZomeModel square;
    square.nodes = {ZVec{}, ZVec{{2, 0, 0, 0, 0, 0}}, ZVec{{2, 0, 2, 0, 0, 0}}, ZVec{{0, 0, 2, 0, 0, 0}}};
    square.struts = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    square.faces = {{0, 1, 2, 3}};
    EXPECT_EQ(read_zome_json(write_zome_json(square)), square);
}

TEST(ZomeJson, LayoutFollowsTheDesign)
{
    ZomeModel one;
    one.nodes = {ZVec{}, ZVec{{2, 0, 0, 0, 0, 0}}};
    one.struts = {{0, 1}};
    const auto doc = nlohmann::json::parse(write_zome_json(one));
    EXPECT_EQ(doc["format"], "zomeify-model");
    EXPECT_EQ(doc["version"], 1);
    EXPECT_EQ(doc["nodes"][1], nlohmann::json::parse("[2,0,0,0,0,0]"));
    EXPECT_EQ(doc["struts"][0], nlohmann::json::parse("[0,1]"));
    EXPECT_TRUE(doc["transform"].contains("scale"));
}

TEST(ZomeJson, FilesConvertBothWays)
{
    ZOME_REQUIRE_SHARED();
    const ZomeModel bunny = read_model_file(test::shared_path("data/vef/bunny.vef"));
    const std::string json_path = test::temp_path("bunny.zome.json"), vef_path = test::temp_path("bunny.vef");
    write_model_file(json_path, bunny);
    write_model_file(vef_path, read_model_file(json_path));
    EXPECT_EQ(read_model_file(vef_path), bunny);
}
