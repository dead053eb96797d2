// The one home of the run options (issue 26): the JSON the page and the Session read gives the
// defaults, every bound is enforced with a message naming the option, the schema the page builds
// its form from says the same, and the pipeline gets what the settings ask for.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/base/errors.h"
#include "core/pipeline/run_settings.h"
#include "core/voxel/advisor.h"

using namespace zomeify;

namespace {

std::string error_of(const std::string& json)
{
    try
    {
        run_settings_from_json(json);
    }
    catch (const InvalidInputError& e)
    {
        return e.what();
    }
    return "";
}

} // namespace

TEST(RunSettings, EmptyJsonGivesTheDefaults)
{
    const RunSettings d;
    EXPECT_EQ(d.resolution, kAutoResolution);
    EXPECT_EQ(d.seconds, 30.0);
    const RunSettings s = run_settings_from_json("{}");
    EXPECT_EQ(run_settings_json(s), run_settings_json(d));
    EXPECT_EQ(s.energy.w_surface, EnergyOptions{}.w_surface);
    // Round trip: the JSON a front end writes reads back to the same settings.
    RunSettings custom;
    custom.resolution = 14;
    custom.seconds = 5;
    custom.seed = 7;
    custom.energy.w_fold = 3;
    EXPECT_EQ(run_settings_json(run_settings_from_json(run_settings_json(custom))), run_settings_json(custom));
}

TEST(RunSettings, EveryBoundIsEnforcedWithTheOptionsName)
{
    for (const OptionBounds& b : run_option_bounds())
    {
        SCOPED_TRACE(b.key);
        const std::string key = b.key;
        const bool weight = key.rfind("weights.", 0) == 0;
        const auto json = [&](double x) {
            nlohmann::json j;
            if (weight)
                j["weights"][key.substr(8)] = x;
            else
                j[key] = x;
            if (key == "seconds")
                j["proposals"] = 1; // a time budget of 0 needs a proposal budget
            return j.dump();
        };
        EXPECT_EQ(error_of(json(b.min)), "");
        EXPECT_EQ(error_of(json(b.max)), "");
        const std::string below = error_of(json(b.min - 1));
        EXPECT_NE(below.find(std::string("'") + b.key + "'"), std::string::npos) << below;
        EXPECT_NE(below.find(b.flag), std::string::npos) << below;
        EXPECT_NE(error_of(json(b.max * 2 + 1)), "");
        if (b.integer)
        {
            EXPECT_NE(error_of(json(b.min + 0.5)), "");
        }
    }
    EXPECT_NE(error_of(R"({"resolution": 1})").find("automatic"), std::string::npos);
    EXPECT_NE(error_of(R"({"target_nodes": 2})"), "");
    EXPECT_NE(error_of(R"({"seconds": 0})").find("unless a proposal budget"), std::string::npos);
    EXPECT_EQ(error_of(R"({"seconds": 0, "proposals": 40000})"), ""); // the page's warm-up run
    EXPECT_NE(error_of(R"({"seconds": "5"})"), "");
    EXPECT_NE(error_of(R"({"initial_only": 1})"), "");
    EXPECT_NE(error_of(R"([1])"), "");
    EXPECT_NE(error_of("{"), "");
}

TEST(RunSettings, SchemaCarriesTheDefaultsBoundsAndPresets)
{
    const nlohmann::json j = nlohmann::json::parse(run_settings_schema_json());
    EXPECT_EQ(j["defaults"], nlohmann::json::parse(run_settings_json()));
    for (const OptionBounds& b : run_option_bounds())
    {
        SCOPED_TRACE(b.key);
        EXPECT_EQ(j["bounds"][b.key]["max"].get<double>(), b.max);
        EXPECT_EQ(j["bounds"][b.key]["flag"], b.flag);
    }
    EXPECT_EQ(j["bounds"]["resolution"]["min"].get<int>(), kMinResolution);
    EXPECT_EQ(j["presets"]["standard"].get<double>(), RunSettings{}.seconds);
    EXPECT_EQ(j["advice_max_resolution"].get<int>(), kAdviceMaxResolution);
}

TEST(RunSettings, PipelineOptionsFollowTheSettings)
{
    RunSettings s;
    s.resolution = 20;
    s.seconds = 3;
    s.proposals = 1000;
    s.target_nodes = 300;
    s.threads = 2;
    s.seed = 9;
    s.initial_only = true;
    s.energy.w_distance = 7;
    const PipelineOptions o = pipeline_options(s);
    EXPECT_EQ(o.resolution, 20);
    EXPECT_TRUE(o.initial_only);
    EXPECT_EQ(o.anneal.seconds, 3.0);
    EXPECT_EQ(o.anneal.max_proposals, 1000u);
    EXPECT_EQ(o.anneal.target_nodes, 300u);
    EXPECT_EQ(o.anneal.threads, 2);
    EXPECT_EQ(o.anneal.seed, 9u);
    EXPECT_EQ(o.anneal.energy.w_distance, 7.0);
    EXPECT_EQ(pipeline_options(RunSettings{}).resolution, kAutoResolution);
    s.seconds = -1;
    EXPECT_THROW(pipeline_options(s), InvalidInputError);
}

TEST(RunSettings, MirrorIsAutoOrOffAndReachesThePipeline)
{
    EXPECT_EQ(run_settings_from_json("{}").mirror, MirrorMode::Off);
    const RunSettings s = run_settings_from_json(R"({"mirror": "auto"})");
    EXPECT_EQ(s.mirror, MirrorMode::Auto);
    EXPECT_EQ(pipeline_options(s).mirror, MirrorMode::Auto);
    EXPECT_EQ(run_settings_from_json(run_settings_json(s)).mirror, MirrorMode::Auto); // round trip
    for (const char* bad : {R"({"mirror": "on"})", R"({"mirror": true})", R"({"mirror": 1})"})
    {
        try
        {
            run_settings_from_json(bad);
            ADD_FAILURE() << bad << " was accepted";
        }
        catch (const InvalidInputError& e)
        {
            EXPECT_STREQ(e.what(), "run option 'mirror' must be \"auto\" or \"off\"");
        }
    }
}
