#include "core/mesh/model_convert.h"

#include <algorithm>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "tests/mesh/mesh_test_util.h"
#include "tests/support/zome_fixtures.h"

using namespace zomeify;

namespace {

std::set<std::pair<uint32_t, uint32_t>> strut_set(const ZomeModel& m)
{
    std::set<std::pair<uint32_t, uint32_t>> out;
    for (const auto& s : m.struts)
        out.insert({std::min(s[0], s[1]), std::max(s[0], s[1])});
    return out;
}

// The message of the InvalidInputError thrown by from_model, or "" if none.
std::string from_model_error(const ZomeModel& model, const FromModelOptions& options = {})
{
    try
    {
        from_model(model, options);
    }
    catch (const InvalidInputError& e)
    {
        return e.what();
    }
    return "";
}

} // namespace

TEST(MeshConvert, RoundTripKeepsNodesFacesAndStruts)
{
    for (const auto& fx : fixtures::closed_models())
    {
        SCOPED_TRACE(fx.name);
        const ZomeMesh mesh = from_model(fx.model);
        EXPECT_EQ(mesh.n_vertices(), fx.model.nodes.size());
        EXPECT_EQ(mesh.n_edges(), fx.model.struts.size());
        EXPECT_EQ(mesh.n_faces(), fx.model.faces.size());
        const ZomeModel back = to_model(mesh);
        EXPECT_EQ(back.nodes, fx.model.nodes);
        EXPECT_EQ(back.faces, fx.model.faces);
        EXPECT_EQ(strut_set(back), strut_set(fx.model));
        // A second round trip is a fixed point, struts included.
        EXPECT_EQ(to_model(from_model(back)), back);
    }
}

TEST(MeshConvert, StrutsMayBeOmitted)
{
    ZomeModel model = fixtures::torus_shell();
    const size_t n_struts = model.struts.size();
    model.struts.clear();
    const ZomeMesh mesh = from_model(model);
    EXPECT_EQ(mesh.n_edges(), n_struts);
}

TEST(MeshConvert, TransformIsPassedThrough)
{
    const ModelTransform t{2.5, {1.0, -2.0, 3.0}};
    EXPECT_EQ(to_model(from_model(fixtures::cube_shell(1)), t).transform, t);
}

TEST(MeshConvert, RejectsInvalidModelsWithClearMessages)
{
    ZomeModel no_faces = fixtures::cube_shell(1);
    no_faces.faces.clear();
    EXPECT_NE(from_model_error(no_faces).find("no faces"), std::string::npos);

    ZomeModel duplicate = fixtures::cube_shell(1);
    duplicate.nodes[3] = duplicate.nodes[1];
    EXPECT_NE(from_model_error(duplicate).find("share the position"), std::string::npos);

    // Two cubes touching at a corner: the shared node has two separate fans.
    const ZomeModel corner = fixtures::voxel_surface({{0, 0, 0}, {1, 1, 1}});
    EXPECT_NE(from_model_error(corner).find("non-manifold"), std::string::npos) << from_model_error(corner);

    // Two cubes touching along an edge: that edge has four faces.
    const ZomeModel edge = fixtures::voxel_surface({{0, 0, 0}, {1, 1, 0}});
    EXPECT_NE(from_model_error(edge).find("more than two faces"), std::string::npos) << from_model_error(edge);

    ZomeModel flipped = fixtures::cube_shell(1);
    std::reverse(flipped.faces[2].begin(), flipped.faces[2].end());
    EXPECT_NE(from_model_error(flipped).find("consistently oriented"), std::string::npos);

    ZomeModel open = fixtures::cube_shell(2);
    open.faces.pop_back();
    open.struts.clear();
    EXPECT_NE(from_model_error(open).find("not closed"), std::string::npos);
    FromModelOptions allow_open;
    allow_open.require_closed = false;
    EXPECT_EQ(from_model_error(open, allow_open), "");

    ZomeModel degenerate = fixtures::cube_shell(1);
    degenerate.faces[0] = {degenerate.faces[0][0], degenerate.faces[0][1]};
    EXPECT_NE(from_model_error(degenerate).find("fewer than three"), std::string::npos);

    ZomeModel lonely = fixtures::cube_shell(1);
    lonely.nodes.push_back(ZVec{{10, 0, 0, 0, 0, 0}});
    EXPECT_NE(from_model_error(lonely).find("lies on no face"), std::string::npos);

    ZomeModel extra_strut = fixtures::cube_shell(1);
    extra_strut.struts.push_back({extra_strut.faces[0][0], extra_strut.faces[0][2]});
    EXPECT_NE(from_model_error(extra_strut).find("not an edge of any face"), std::string::npos);

    ZomeModel missing_strut = fixtures::cube_shell(1);
    missing_strut.struts.pop_back();
    EXPECT_NE(from_model_error(missing_strut).find("edges but the model lists"), std::string::npos);

    // The axis octahedron: its edges (−φ, φ, 0) are not Zome vectors.
    ZomeModel octa;
    const int32_t p = 2;
    octa.nodes = {ZVec{{p, 0, 0, 0, 0, 0}},  ZVec{{-p, 0, 0, 0, 0, 0}}, ZVec{{0, 0, p, 0, 0, 0}},
                  ZVec{{0, 0, -p, 0, 0, 0}}, ZVec{{0, 0, 0, 0, p, 0}},  ZVec{{0, 0, 0, 0, -p, 0}}};
    octa.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    EXPECT_NE(from_model_error(octa).find("not a Zome vector"), std::string::npos) << from_model_error(octa);
    FromModelOptions any_vector;
    any_vector.require_zome = false;
    const ZomeMesh octa_mesh = from_model(octa, any_vector);
    const ValidationReport r = validate(octa_mesh);
    EXPECT_EQ(r.count(MeshProblem::NonZomeEdge), 12u) << r.message();
    EXPECT_EQ(r.genus, 0);
}
