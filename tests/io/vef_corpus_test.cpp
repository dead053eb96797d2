// VEF read as vZome reads it (core/io/vef.h; vZome's VefParser, read to learn its rules): a corpus
// written for these tests from the format's rules (tests/data/vef/corpus), one file per case, with
// what vZome does with it and what zomeify answers: the counts of a model, or the reason it is not
// one, in words a vZome user knows.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/io/model_io.h"
#include "core/io/vef.h"
#include "tests/support/paths.h"

using namespace zomeify;

namespace {

struct Case
{
    const char* file;
    const char* vzome; // what vZome does with the file
    size_t nodes;      // the model read (when `refusal` is empty)
    size_t struts;
    size_t balls;        // vertices the file gives a ball
    size_t notes;        // sentences for the person loading it
    const char* refusal; // a part of the one-line reason, when it is no model
};

const std::vector<Case> kCases = {
    {"faces_only_shape.vef", "a part shape: panels, no ball, no strut", 0, 0, 0, 0,
     "it is a shape, not a Zome model: it has no struts and no balls (only faces"},
    {"ten_balls_of_twenty.vef", "10 balls (the ball list); the other 10 vertices show nothing", 10, 0, 10, 1, ""},
    {"strut_end_without_ball.vef", "2 balls and 2 struts, one strut end bare", 3, 2, 2, 1, ""},
    {"vertices_only.vef", "nothing to show: sections after the vertices are optional, no ball list in version 10", 0, 0,
     0, 0, "it has no struts and no balls"},
    {"unversioned.vef", "read without the header (version 0): every vertex a ball", 2, 1, 2, 0, ""},
    {"trailing_text.vef", "text after the ball list ignored", 2, 1, 2, 0, ""},
    {"green_strut.vef", "a green strut (blue x + blue y)", 0, 0, 0, 0,
     "is a green strut: green struts are not supported yet"},
    {"other_field.vef", "refused unless the current model's field is sqrtPhi", 0, 0, 0, 0,
     "it is made in vZome's 'sqrtPhi' field; Zometool models are made in the golden field"},
    {"four_d.vef", "a 4D point, shown projected", 0, 0, 0, 0, "a 4D model (vertex 1 has a W coordinate)"},
    {"scale_two.vef", "a strut twice a B1 long, which no Zometool strut is", 2, 1, 2, 1, ""},
    {"too_large.vef", "exact big numbers (BigInteger)", 0, 0, 0, 0, "has a number too large for exact arithmetic here"},
    {"version5_all_balls.vef", "before version 6 every vertex is a ball", 2, 1, 2, 0, ""},
};

} // namespace

TEST(VefCorpus, EachFileIsReadAsVzomeReadsItOrRefusedWithItsReason)
{
    for (const Case& c : kCases)
    {
        SCOPED_TRACE(std::string(c.file) + " (vZome: " + c.vzome + ")");
        const std::string path = test::test_data_path(std::string("vef/corpus/") + c.file);
        if (*c.refusal)
        {
            try
            {
                read_vef_file(path);
                ADD_FAILURE() << "read, but should be refused";
            }
            catch (const InvalidInputError& e)
            {
                const std::string what = e.what();
                EXPECT_NE(what.find(c.refusal), std::string::npos) << what;
                EXPECT_EQ(what.find('\n'), std::string::npos) << "one line";
            }
            continue;
        }
        VefReadInfo info;
        const ZomeModel m = read_vef_file(path, &info);
        EXPECT_EQ(m.nodes.size(), c.nodes);
        EXPECT_EQ(m.struts.size(), c.struts);
        EXPECT_EQ(info.balls, c.balls);
        EXPECT_EQ(info.notes.size(), c.notes);
    }
}

TEST(VefCorpus, NotesReachTheLoadersAndSayWhatTheBuilderNeeds)
{
    std::vector<std::string> notes;
    read_model_file(test::test_data_path("vef/corpus/strut_end_without_ball.vef"), &notes);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0], "1 strut end has no ball in the file (vZome draws none there); a builder needs one at each, "
                        "so they are counted as balls");
    VefReadInfo info;
    read_vef_file(test::test_data_path("vef/corpus/scale_two.vef"), &info);
    EXPECT_TRUE(info.scale_set_aside);
    read_vef_file(test::test_data_path("vef/corpus/ten_balls_of_twenty.vef"), &info);
    EXPECT_EQ(info.vertices_dropped, 10u);
}
