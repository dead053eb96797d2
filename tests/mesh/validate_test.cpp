#include "core/mesh/validate.h"

#include <gtest/gtest.h>

#include "core/mesh/circulators.h"
#include "core/mesh/model_convert.h"
#include "core/zome/slots.h"
#include "tests/mesh/mesh_test_util.h"
#include "tests/support/zome_fixtures.h"

using namespace zomeify;

namespace {

// Exposes the append-only primitives, to assemble connectivity the public edits never produce.
class RawMesh : public ZomeMesh
{
public:
    using SurfaceMesh::new_edge;
    using SurfaceMesh::new_face;
};

} // namespace

TEST(MeshValidate, FixturesAreValidWithExpectedGenus)
{
    for (const auto& fx : fixtures::closed_models())
    {
        SCOPED_TRACE(fx.name);
        const ZomeMesh mesh = from_model(fx.model);
        const ValidationReport r = validate(mesh);
        EXPECT_TRUE(r.ok()) << r.message();
        EXPECT_TRUE(r.topology_known);
        EXPECT_EQ(r.genus, fx.genus);
        ASSERT_EQ(r.components.size(), 1u);
        EXPECT_EQ(r.components[0].genus, fx.genus);
        EXPECT_EQ(r.euler_characteristic, 2 - 2 * fx.genus);
        EXPECT_EQ(r.boundary_loops, 0u);
        EXPECT_NE(r.message().find("genus " + std::to_string(fx.genus)), std::string::npos) << r.message();
    }
}

TEST(MeshValidate, GenusPerComponent)
{
    // A torus and a separate cube in one model: two components, genus 1 + 0.
    std::vector<fixtures::Cell> cells = fixtures::torus_cells();
    cells.push_back({6, 0, 0});
    const ZomeMesh mesh = from_model(fixtures::voxel_surface(cells));
    const ValidationReport r = validate(mesh);
    EXPECT_TRUE(r.ok()) << r.message();
    ASSERT_EQ(r.components.size(), 2u);
    EXPECT_EQ(r.components[0].genus + r.components[1].genus, 1);
    EXPECT_EQ(r.genus, 1);
    EXPECT_EQ(r.euler_characteristic, 2);
}

TEST(MeshValidate, PentagonsNeedThePolygonFlag)
{
    const ZomeMesh mesh = from_model(fixtures::dodecahedron());
    const ValidationReport strict = validate(mesh);
    EXPECT_EQ(strict.count(MeshProblem::FaceSize), 12u);
    EXPECT_EQ(strict.total_problems(), 12u) << strict.message();
    ValidateOptions polygons;
    polygons.tri_quad_only = false;
    EXPECT_TRUE(test::is_valid(mesh, polygons));
    EXPECT_EQ(validate(mesh, polygons).genus, 0);
}

TEST(MeshValidate, CatchesWrongSlot)
{
    ZomeMesh mesh = from_model(fixtures::cube_shell(2));
    const Halfedge h = SurfaceMesh::halfedge(Edge(5), 0);
    mesh.set_vector_id_unchecked(h, static_cast<uint8_t>((mesh.vector_id(h) + 3) % kVectorCount));
    const ValidationReport r = validate(mesh);
    EXPECT_EQ(r.count(MeshProblem::WrongVectorId), 1u) << r.message();
    EXPECT_NE(r.message().find("e5"), std::string::npos) << r.message();
}

TEST(MeshValidate, CatchesDuplicatePosition)
{
    ZomeMesh mesh = from_model(fixtures::cube_shell(2));
    mesh.set_position_unchecked(Vertex(7), mesh.position(Vertex(3)));
    const ValidationReport r = validate(mesh);
    EXPECT_TRUE(r.has(MeshProblem::DuplicatePosition)) << r.message();
    EXPECT_TRUE(r.has(MeshProblem::PositionIndex)) << r.message();

    ZomeMesh twice = from_model(fixtures::cube_shell(1));
    twice.add_vertex_unchecked(twice.position(Vertex(0)));
    const ValidationReport r2 = validate(twice);
    EXPECT_TRUE(r2.has(MeshProblem::DuplicatePosition)) << r2.message();
    EXPECT_TRUE(r2.has(MeshProblem::LowValence)) << r2.message();
}

TEST(MeshValidate, CatchesNonZomeEdge)
{
    // A diagonal of a B1 square is (φ, φ, 0): no Zome strut has that direction.
    ZomeMesh mesh = from_model(fixtures::cube_shell(1));
    const Face f(0);
    const Halfedge h = mesh.halfedge(f);
    const Vertex a = mesh.to_vertex(h);
    const Vertex c = mesh.to_vertex(mesh.next(mesh.next(h)));
    ASSERT_FALSE(mesh.is_zome_pair(a, c));
    const Halfedge d = mesh.split_face(f, a, c);
    EXPECT_EQ(mesh.vector_id(d), kNoZomeVector);
    const ValidationReport r = validate(mesh);
    EXPECT_EQ(r.count(MeshProblem::NonZomeEdge), 1u) << r.message();
    EXPECT_EQ(r.count(MeshProblem::WrongVectorId), 0u) << r.message();
    EXPECT_TRUE(test::is_valid(mesh, [] {
        ValidateOptions o;
        o.check_zome = false;
        return o;
    }()));
}

TEST(MeshValidate, CatchesNonManifoldVertex)
{
    // Two faces of the icosahedron that share only a node: a bowtie.
    const ZomeModel ico = fixtures::icosahedron();
    ZomeMesh full = from_model(ico);
    const Vertex v(0);
    std::vector<Face> fan;
    for (Face f : incident_faces(full, v))
        fan.push_back(f);
    ASSERT_EQ(fan.size(), 5u);

    ZomeMesh mesh;
    for (const ZVec& p : ico.nodes)
        mesh.add_vertex(p);
    for (Face f : {fan[0], fan[2]})
    {
        std::vector<Vertex> corners;
        for (Vertex w : face_vertices(full, f))
            corners.push_back(w);
        ASSERT_TRUE(mesh.add_face(corners).is_valid());
    }
    ValidateOptions o = test::open_options();
    ValidationReport r = validate(mesh, o);
    EXPECT_EQ(r.count(MeshProblem::NonManifoldVertex), 1u) << r.message();
    EXPECT_NE(r.message().find("v0"), std::string::npos) << r.message();
    // Closing the gap with the face between them makes it a manifold disc again.
    std::vector<Vertex> corners;
    for (Vertex w : face_vertices(full, fan[1]))
        corners.push_back(w);
    ASSERT_TRUE(mesh.add_face(corners).is_valid());
    r = validate(mesh, o);
    EXPECT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r.boundary_loops, 1u);
    EXPECT_EQ(r.genus, 0);
    // Closed-surface rules still see the boundary.
    EXPECT_TRUE(validate(mesh).has(MeshProblem::Boundary));
}

TEST(MeshValidate, CatchesDoublyConnectedPair)
{
    // A sphere of four triangles on nodes a, b, c, d in which a and b are joined by two edges:
    // (a,b,c) and (b,a,d) use edge 1, (b,a,c) and (a,b,d) use edge 2.
    RawMesh m;
    const Vertex a = m.add_vertex(ZVec{{0, 0, 0, 0, 0, 0}});
    const Vertex b = m.add_vertex(ZVec{{0, 2, 0, 0, 0, 0}});
    const Vertex c = m.add_vertex(ZVec{{0, 0, 0, 2, 0, 0}});
    const Vertex d = m.add_vertex(ZVec{{0, 0, 0, 0, 0, 2}});
    const Halfedge ab1 = m.new_edge(a, b), ab2 = m.new_edge(a, b);
    const Halfedge bc = m.new_edge(b, c), ca = m.new_edge(c, a);
    const Halfedge ad = m.new_edge(a, d), db = m.new_edge(d, b);
    const auto O = [](Halfedge h) { return SurfaceMesh::opposite(h); };
    const auto face = [&](Halfedge x, Halfedge y, Halfedge z) {
        const Face f = m.new_face();
        m.set_next(x, y);
        m.set_next(y, z);
        m.set_next(z, x);
        for (Halfedge h : {x, y, z})
            m.set_face(h, f);
        m.set_halfedge(f, x);
    };
    face(ab1, bc, ca);          // a b c
    face(O(ab2), O(ca), O(bc)); // b a c: b→a (edge 2), a→c, c→b
    face(O(ab1), ad, db);       // b a d
    face(ab2, O(db), O(ad));    // a b d
    m.set_halfedge(a, ab1);
    m.set_halfedge(b, bc);
    m.set_halfedge(c, ca);
    m.set_halfedge(d, db);
    ValidateOptions o;
    o.min_valence = 0;
    const ValidationReport r = validate(m, o);
    EXPECT_EQ(r.count(MeshProblem::DoubleEdge), 1u) << r.message();
    EXPECT_EQ(r.count(MeshProblem::SlotConflict), 2u) << r.message(); // same strut twice, at a and at b
    EXPECT_EQ(r.count(MeshProblem::Connectivity), 0u) << r.message();
    EXPECT_EQ(r.count(MeshProblem::NonManifoldVertex), 0u) << r.message();
    EXPECT_EQ(r.genus, 0);
}

TEST(MeshValidate, CatchesSlotConflict)
{
    // Triangles (O, P, Q) and (O, Q, R) with P and R in the same slot of O (sizes 0 and 1).
    const int s = 0;
    const ZVec o{}, p = zome_vector(vector_id(s, 0)), r = zome_vector(vector_id(s, 1));
    ZVec q;
    bool found = false;
    for (const ZVec& t : zome_vectors())
        if (vector_id_of(t - p) >= 0 && vector_id_of(r - t) >= 0 && slot_of(t) / 2 != s / 2)
        {
            q = t;
            found = true;
            break;
        }
    ASSERT_TRUE(found);
    ZomeMesh mesh;
    const Vertex vo = mesh.add_vertex(o), vp = mesh.add_vertex(p), vq = mesh.add_vertex(q), vr = mesh.add_vertex(r);
    mesh.add_triangle(vo, vp, vq);
    mesh.add_triangle(vo, vq, vr);
    const ValidationReport rep = validate(mesh, test::open_options());
    EXPECT_EQ(rep.count(MeshProblem::SlotConflict), 1u) << rep.message();
    EXPECT_EQ(rep.total_problems(), 1u) << rep.message();
    EXPECT_TRUE(mesh.find_slot(vo, s).is_valid());
    EXPECT_FALSE(mesh.find_slot(vo, opposite_slot(s)).is_valid());
}

TEST(MeshValidate, CatchesLowValenceAndBrokenLinks)
{
    ZomeMesh mesh = from_model(fixtures::cube_shell(1));
    ValidateOptions four;
    four.min_valence = 4;
    EXPECT_EQ(validate(mesh, four).count(MeshProblem::LowValence), 8u);

    // next of one halfedge redirected into another face.
    const Halfedge h = mesh.halfedge(Face(0));
    mesh.set_next(h, mesh.halfedge(Face(3)));
    const ValidationReport r = validate(mesh);
    EXPECT_TRUE(r.has(MeshProblem::Connectivity)) << r.message();
    EXPECT_FALSE(r.topology_known);
}
