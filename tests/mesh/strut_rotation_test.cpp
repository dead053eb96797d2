// Rotation systems: the faces of every closed fixture are their rotation system, the geometric
// guess is right on convex models, and faces that are no closed surface over the struts have none.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/mesh/recover_faces.h"
#include "core/mesh/strut_rotation.h"
#include "tests/support/zome_fixtures.h"

namespace zomeify {
namespace {

std::set<std::vector<uint32_t>> face_set(std::vector<std::vector<uint32_t>> faces)
{
    std::set<std::vector<uint32_t>> out;
    for (auto& f : faces)
    {
        std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
        out.insert(f);
    }
    return out;
}

TEST(StrutRotation, FacesOfEveryClosedFixtureAreTheirRotation)
{
    for (const auto& fixture : fixtures::closed_models())
    {
        SCOPED_TRACE(fixture.name);
        const ZomeModel& m = fixture.model;
        const auto rotation = rotation_of_faces(m.nodes.size(), m.struts, m.faces);
        ASSERT_TRUE(rotation.has_value());
        EXPECT_EQ(face_set(trace_faces(*rotation)), face_set(m.faces));
    }
}

TEST(StrutRotation, GuessIsRightOnConvexModels)
{
    for (const ZomeModel& m : {fixtures::icosahedron(), fixtures::cube_shell(3)})
    {
        const Rotation guess = guess_rotation(m.nodes, m.struts);
        EXPECT_EQ(face_set(trace_faces(guess)), face_set(m.faces));
    }
}

TEST(StrutRotation, OpenOrForeignFacesHaveNoRotation)
{
    ZomeModel m = fixtures::icosahedron();
    auto open = m.faces;
    open.pop_back(); // three struts now lie on one face only
    EXPECT_FALSE(rotation_of_faces(m.nodes.size(), m.struts, open).has_value());
    auto doubled = m.faces;
    doubled.push_back(m.faces.front()); // a face twice
    EXPECT_FALSE(rotation_of_faces(m.nodes.size(), m.struts, doubled).has_value());
    auto extra_strut = m.struts;
    extra_strut.push_back({0, static_cast<uint32_t>(m.nodes.size() - 1)}); // a strut on no face
    EXPECT_FALSE(rotation_of_faces(m.nodes.size(), extra_strut, m.faces).has_value());
}

} // namespace
} // namespace zomeify
