// Bad model files: each gets a one-line InvalidInputError naming the problem, never a crash.
#include <random>

#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/model_io.h"
#include "core/io/vef.h"
#include "core/io/zome_json.h"
#include "tests/support/paths.h"

using namespace zomeify;

namespace {

std::string error_of(const std::string& bytes, const std::string& name)
{
    try
    {
        read_model_buffer(bytes, name);
    }
    catch (const InvalidInputError& e)
    {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "message is not one line: " << msg;
        return msg;
    }
    ADD_FAILURE() << "no error for " << name << ": " << bytes.substr(0, 80);
    return {};
}

const char* kHeader = "vZome VEF 6 field golden ";

} // namespace

TEST(BadModelInput, VefProblemsAreNamed)
{
    EXPECT_NE(error_of("", "a.vef").find("empty"), std::string::npos);
    EXPECT_NE(error_of("hello world", "a.vef").find("vZome VEF"), std::string::npos);
    EXPECT_NE(error_of(std::string(kHeader) + "2 (0,0) (0,0) (0,0) (0,0) (0,0) (4,2)", "a.vef").find("truncated"),
              std::string::npos);
    // A strut of length √2 along x + y: a green strut.
    EXPECT_NE(error_of(std::string(kHeader) + "2 (0,0) (0,0) (0,0) (0,0) (0,0) (0,2) (0,2) (0,0) 1 0 1", "a.vef")
                  .find("is a green strut: green struts are not supported yet"),
              std::string::npos);
    // Along x + 2y: no Zometool strut at all.
    EXPECT_NE(error_of(std::string(kHeader) + "2 (0,0) (0,0) (0,0) (0,0) (0,0) (0,2) (0,4) (0,0) 1 0 1", "a.vef")
                  .find("not a Zome strut"),
              std::string::npos);
    EXPECT_NE(error_of(std::string(kHeader) + "2 (0,0) (0,0) (0,0) (0,0) (0,0) (4,2) (0,0) (0,0) 1 0 7", "a.vef")
                  .find("refers to vertex 7"),
              std::string::npos);
    EXPECT_NE(error_of(std::string(kHeader) + "99999999999 (0,0) (0,0) (0,0) (0,0)", "a.vef").find("count"),
              std::string::npos);
    EXPECT_NE(error_of(std::string(kHeader) + "1000 (0,0) (0,0) (0,0) (0,0)", "a.vef").find("larger than the file"),
              std::string::npos);
    EXPECT_NE(error_of(std::string(kHeader) + "1 (0,0) (x,1) (0,0) (0,0) 0", "a.vef").find("not a number"),
              std::string::npos);
    EXPECT_NE(error_of("vZome VEF 6 field rootTwo 0 0", "a.vef").find("made in the golden field"), std::string::npos);
    EXPECT_NE(
        error_of(std::string(kHeader) + "1 (0,0) (99999999999999,0) (0,0) (0,0) 0 0 1 0", "a.vef").find("too large"),
        std::string::npos);
}

TEST(BadModelInput, JsonProblemsAreNamed)
{
    const std::string head = R"({"format":"zomeify-model","version":1,)";
    EXPECT_NE(error_of("", "a.zome.json").find("empty"), std::string::npos);
    EXPECT_NE(error_of("{\"format\":\"zomeify-model\"", "a.zome.json").find("syntax"), std::string::npos);
    EXPECT_NE(error_of(R"({"format":"other"})", "a.zome.json").find("format"), std::string::npos);
    EXPECT_NE(error_of(head + R"("nodes":[[0,0,0,0,0,0],[0,2,0,2,0,0]],"struts":[[0,1]]})", "a.zome.json")
                  .find("not a Zome strut"),
              std::string::npos);
    EXPECT_NE(error_of(head + R"("nodes":[[0,0,0,0,0,0],[2,0,0,0,0,0]],"struts":[[0,5]]})", "a.zome.json")
                  .find("does not exist"),
              std::string::npos);
    EXPECT_NE(
        error_of(head + R"("nodes":[[0,0,0,0,0,0],[0,0,0,0,0,0]],"struts":[]})", "a.zome.json").find("same position"),
        std::string::npos);
    EXPECT_NE(error_of(head + R"("nodes":[[0,0,0,0,0,1e300]],"struts":[]})", "a.zome.json").find("integer"),
              std::string::npos);
    EXPECT_NE(error_of(head + R"("nodes":[[0,0,0,0,0,99999999999]],"struts":[]})", "a.zome.json").find("range"),
              std::string::npos);
    EXPECT_NE(error_of(head + R"("nodes":[[0,0,0,0,0]],"struts":[]})", "a.zome.json").find("6 integers"),
              std::string::npos);
    EXPECT_NE(
        error_of(R"({"format":"zomeify-model","version":99,"nodes":[],"struts":[]})", "a.zome.json").find("version 99"),
        std::string::npos);
    // Two struts in one slot of a ball: 0→1 and 0→2 both along +x (b1 and b0... same slot).
    EXPECT_NE(
        error_of(head + R"("nodes":[[0,0,0,0,0,0],[2,0,0,0,0,0],[0,2,0,0,0,0]],"struts":[[0,1],[0,2]]})", "a.zome.json")
            .find("ball hole"),
        std::string::npos);
    EXPECT_NE(error_of("{}", "a.obj").find("unknown model format"), std::string::npos);
}

TEST(BadModelInput, TruncatedAndMutatedFilesNeverCrash)
{
    ZOME_REQUIRE_SHARED();
    const std::string vef = read_file_bytes(test::shared_path("data/vef/bunny.vef"));
    const std::string json = write_zome_json(read_vef(vef));
    std::mt19937 rng(12345);
    for (const auto& [text, name] : {std::pair{vef, std::string("b.vef")}, std::pair{json, std::string("b.zome.json")}})
    {
        // Every truncation point on a coarse grid: a shorter file is an error or a smaller valid model.
        for (size_t cut = 0; cut < text.size(); cut += 1 + text.size() / 300)
        {
            try
            {
                read_model_buffer(text.substr(0, cut), name);
            }
            catch (const InvalidInputError&)
            {
            }
        }
        // Random byte edits.
        for (int trial = 0; trial < 300; ++trial)
        {
            std::string m = text;
            for (int k = 0; k < 4; ++k)
                m[rng() % m.size()] = static_cast<char>(rng() % 256);
            try
            {
                read_model_buffer(m, name);
            }
            catch (const InvalidInputError&)
            {
            }
        }
    }
    // Pure random bytes.
    for (int trial = 0; trial < 200; ++trial)
    {
        std::string junk(rng() % 2000, '\0');
        for (char& c : junk)
            c = static_cast<char>(rng() % 256);
        EXPECT_THROW(read_model_buffer(junk, "r.vef"), InvalidInputError);
        EXPECT_THROW(read_model_buffer(junk, "r.zome.json"), InvalidInputError);
    }
}

// Found by fuzzing (tests/fuzz, target zome_json): a number beyond double's range made the JSON
// parser throw its own out_of_range exception instead of a one-line InvalidInputError.
TEST(BadModelInput, JsonNumberOutOfRange)
{
    const std::string doc = R"({"format":"zomeify-model","version":1,"nodes":[[1e3000,0,0,0,0,0]],"struts":[]})";
    EXPECT_NE(error_of(doc, "m.zome.json").find("too large"), std::string::npos);
    EXPECT_NE(error_of(R"({"format":"zomeify-model","version":-1e999})", "m.zome.json").find("too large"),
              std::string::npos);
}
