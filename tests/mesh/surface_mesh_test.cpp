#include "core/mesh/surface_mesh.h"

#include <algorithm>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/topology_error.h"
#include "tests/mesh/mesh_test_util.h"
#include "tests/support/zome_fixtures.h"

using namespace zomeify;

namespace {

std::vector<Vertex> corners(const std::vector<uint32_t>& face)
{
    std::vector<Vertex> out;
    for (uint32_t i : face)
        out.push_back(Vertex(i));
    return out;
}

// A random half of 0 .. n-1, in random order.
std::vector<size_t> random_half(size_t n, std::mt19937& rng)
{
    std::vector<size_t> order(n);
    for (size_t i = 0; i < n; ++i)
        order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    order.resize(n / 2);
    return order;
}

} // namespace

TEST(MeshHandles, TypedIndices)
{
    const Vertex v(3);
    EXPECT_TRUE(v.is_valid());
    EXPECT_EQ(v.idx(), 3u);
    EXPECT_FALSE(Vertex().is_valid());
    EXPECT_LT(Vertex(2), Vertex(3));
    EXPECT_EQ(std::hash<Face>()(Face(9)), 9u);
    std::ostringstream os;
    os << Vertex(12) << ' ' << Halfedge(7) << ' ' << Edge(3) << ' ' << Face(0) << ' ' << Face();
    EXPECT_EQ(os.str(), "v12 h7 e3 f0 f-");
    EXPECT_EQ(SurfaceMesh::opposite(Halfedge(6)), Halfedge(7));
    EXPECT_EQ(SurfaceMesh::edge(Halfedge(7)), Edge(3));
    EXPECT_EQ(SurfaceMesh::halfedge(Edge(3), 1), Halfedge(7));
}

TEST(MeshProperties, AddGetRemoveAndCopy)
{
    SurfaceMesh mesh;
    auto weight = mesh.add_vertex_property<double>("v:weight", 1.5);
    const Vertex a = mesh.add_vertex();
    const Vertex b = mesh.add_vertex();
    EXPECT_EQ(weight[a], 1.5);
    weight[b] = 4.0;
    EXPECT_THROW(mesh.add_vertex_property<double>("v:weight"), std::invalid_argument);
    EXPECT_TRUE(mesh.get_vertex_property<double>("v:weight").is_valid());
    EXPECT_FALSE(mesh.get_vertex_property<int>("v:weight").is_valid());
    const SurfaceMesh copy = mesh;
    weight[b] = 5.0;
    EXPECT_EQ(copy.get_vertex_property<double>("v:weight")[b], 4.0);
    mesh.remove_property(weight);
    EXPECT_FALSE(weight.is_valid());
    EXPECT_FALSE(mesh.get_vertex_property<double>("v:weight").is_valid());
    auto tag = mesh.add_face_property<int>("f:tag", 7);
    const Vertex c = mesh.add_vertex();
    const Face f = mesh.add_triangle(a, b, c);
    EXPECT_EQ(tag[f], 7);
}

TEST(MeshSurface, TriangleAndQuadPrimitives)
{
    SurfaceMesh m;
    const Vertex a = m.add_vertex(), b = m.add_vertex(), c = m.add_vertex(), d = m.add_vertex();
    const Face q = m.add_quad(a, b, c, d);
    EXPECT_EQ(m.valence(q), 4u);
    EXPECT_EQ(m.n_edges(), 4u);
    EXPECT_TRUE(m.is_boundary(a));
    EXPECT_TRUE(m.is_boundary(q));
    EXPECT_TRUE(test::is_valid(m, test::open_options()));
    EXPECT_EQ(validate(m, test::open_options()).boundary_loops, 1u);

    EXPECT_TRUE(m.is_split_ok(q, a, c));
    EXPECT_FALSE(m.is_split_ok(q, a, b));
    const Halfedge diag = m.split_face(q, a, c);
    EXPECT_EQ(m.from_vertex(diag), a);
    EXPECT_EQ(m.to_vertex(diag), c);
    EXPECT_EQ(m.n_faces(), 2u);
    EXPECT_EQ(m.valence(m.face(diag)), 3u);
    EXPECT_EQ(m.valence(m.face(SurfaceMesh::opposite(diag))), 3u);
    EXPECT_FALSE(m.is_split_ok(m.face(diag), a, c));
    EXPECT_TRUE(test::is_valid(m, test::open_options()));

    EXPECT_FALSE(m.is_remove_edge_ok(m.find_edge(a, b))); // a boundary edge has one face
    ASSERT_TRUE(m.is_remove_edge_ok(SurfaceMesh::edge(diag)));
    const Face merged = m.remove_edge(SurfaceMesh::edge(diag));
    EXPECT_EQ(m.valence(merged), 4u);
    EXPECT_EQ(m.n_faces(), 1u);
    EXPECT_EQ(m.n_edges(), 4u);
    EXPECT_TRUE(test::is_valid(m, test::open_options()));
}

TEST(MeshSurface, AddFaceRefusesNonManifoldConfigurations)
{
    SurfaceMesh m;
    std::vector<Vertex> v;
    for (int i = 0; i < 6; ++i)
        v.push_back(m.add_vertex());
    m.add_triangle(v[0], v[1], v[2]);
    const Vertex same_dir[3] = {v[0], v[1], v[3]};
    EXPECT_EQ(m.check_add_face(same_dir), AddFaceStatus::ComplexEdge);
    EXPECT_THROW(m.add_face(same_dir), TopologyError);
    EXPECT_FALSE(m.try_add_face(same_dir).is_valid());
    const Vertex repeated[3] = {v[3], v[4], v[3]};
    EXPECT_EQ(m.check_add_face(repeated), AddFaceStatus::RepeatedVertex);
    const Vertex two[2] = {v[3], v[4]};
    EXPECT_EQ(m.check_add_face(two), AddFaceStatus::TooFewVertices);
    const Vertex missing[3] = {v[3], v[4], Vertex(99)};
    EXPECT_EQ(m.check_add_face(missing), AddFaceStatus::InvalidVertex);
    EXPECT_EQ(m.n_faces(), 1u);
    EXPECT_TRUE(test::is_valid(m, test::open_options()));
}

TEST(MeshSurface, AddFacesInRandomOrderBuildsEveryFixture)
{
    std::mt19937 rng(12345);
    for (const auto& fx : fixtures::closed_models())
    {
        SCOPED_TRACE(fx.name);
        for (int round = 0; round < 5; ++round)
        {
            std::vector<size_t> order(fx.model.faces.size());
            for (size_t i = 0; i < order.size(); ++i)
                order[i] = i;
            std::shuffle(order.begin(), order.end(), rng);
            ZomeMesh mesh;
            for (const ZVec& p : fx.model.nodes)
                mesh.add_vertex(p);
            for (size_t i : order)
            {
                const auto vs = corners(fx.model.faces[i]);
                const AddFaceStatus status = mesh.check_add_face(vs);
                ASSERT_EQ(status, AddFaceStatus::Ok) << "face " << i << ": " << to_string(status);
                mesh.add_face(vs);
                const ValidationReport r = validate(mesh, test::open_options());
                // Intermediate states may pinch at a vertex; links must always be sound.
                ASSERT_FALSE(r.has(MeshProblem::Connectivity)) << r.message();
                ASSERT_FALSE(r.has(MeshProblem::SlotConflict)) << r.message();
            }
            const ValidationReport r = validate(mesh);
            ASSERT_TRUE(r.ok()) << r.message();
            EXPECT_EQ(r.genus, fx.genus);
        }
    }
}

TEST(MeshSurface, RemoveFacesAndRefill)
{
    std::mt19937 rng(777);
    for (const auto& fx : fixtures::closed_models())
    {
        SCOPED_TRACE(fx.name);
        ZomeMesh mesh = from_model(fx.model);
        // Remove a random half of the faces, one by one, then put them back in another order.
        std::vector<size_t> order = random_half(fx.model.faces.size(), rng);
        for (size_t i : order)
        {
            mesh.remove_face(Face(static_cast<MeshIndex>(i)));
            const ValidationReport r = validate(mesh, test::open_options());
            ASSERT_FALSE(r.has(MeshProblem::Connectivity)) << r.message();
        }
        EXPECT_EQ(mesh.n_faces(), fx.model.faces.size() - order.size());
        std::shuffle(order.begin(), order.end(), rng);
        for (size_t i : order)
            ASSERT_TRUE(mesh.add_face(corners(fx.model.faces[i])).is_valid());
        ASSERT_TRUE(test::is_valid(mesh));
        EXPECT_EQ(validate(mesh).genus, fx.genus);
        EXPECT_EQ(mesh.n_edges(), fx.model.struts.size());
    }
}

// With slot reuse on, refilling the removed faces takes their slots (and their struts' slots)
// again: the arrays do not grow, the counts stay exact, a user property starts from its default.
TEST(MeshSurface, SlotReuseRefillsDeletedSlots)
{
    std::mt19937 rng(778);
    for (const auto& fx : fixtures::closed_models())
    {
        SCOPED_TRACE(fx.name);
        ZomeMesh mesh = from_model(fx.model);
        mesh.set_slot_reuse(true);
        auto tag = mesh.add_face_property<int>("f:tag", -1);
        for (Face f : faces(mesh))
            tag[f] = 5;
        const size_t faces_size = mesh.faces_size(), edges_size = mesh.edges_size();
        std::vector<size_t> order = random_half(fx.model.faces.size(), rng);
        for (size_t i : order)
            mesh.remove_face(Face(static_cast<MeshIndex>(i)));
        ASSERT_TRUE(mesh.has_garbage());
        std::shuffle(order.begin(), order.end(), rng);
        for (size_t i : order)
        {
            const Face f = mesh.add_face(corners(fx.model.faces[i]));
            ASSERT_TRUE(f.is_valid());
            EXPECT_LT(f.idx(), faces_size) << "appended instead of reusing a slot";
            EXPECT_EQ(tag[f], -1) << "a reused slot kept an old property value";
        }
        EXPECT_EQ(mesh.faces_size(), faces_size);
        EXPECT_EQ(mesh.edges_size(), edges_size);
        EXPECT_FALSE(mesh.has_garbage());
        ASSERT_TRUE(test::is_valid(mesh));
        EXPECT_EQ(validate(mesh).genus, fx.genus);
        EXPECT_EQ(mesh.n_faces(), fx.model.faces.size());
        EXPECT_EQ(mesh.n_edges(), fx.model.struts.size());
        // Every strut got its Zome vector again (ZomeMesh's on_edge_added on a reused slot).
        for (Halfedge h : halfedges(mesh))
            ASSERT_EQ(static_cast<int>(mesh.vector_id(h)), vector_id_of(mesh.vector(h)));
    }
}

// Off (the default), new elements always append; a slot freed before switching on is not refilled
// after garbage collection either (the lists start over).
TEST(MeshSurface, SlotReuseOffAppends)
{
    ZomeMesh mesh = from_model(fixtures::icosahedron());
    const std::vector<uint32_t> face = fixtures::icosahedron().faces[3];
    mesh.remove_face(Face(3));
    const Face f = mesh.add_face(corners(face));
    EXPECT_EQ(f.idx(), 20u);
    mesh.set_slot_reuse(true);
    mesh.remove_face(f);
    mesh.garbage_collection();
    const Face g = mesh.add_face(corners(face));
    EXPECT_EQ(g.idx(), mesh.faces_size() - 1);
    ASSERT_TRUE(test::is_valid(mesh));
}

TEST(MeshSurface, RemoveVertexLeavesItsLinkAsAHole)
{
    ZomeMesh mesh = from_model(fixtures::icosahedron());
    const Vertex v(4);
    std::vector<Vertex> ring;
    for (Vertex w : adjacent_vertices(mesh, v))
        ring.push_back(w);
    ASSERT_EQ(ring.size(), 5u);
    const ZVec p = mesh.position(v);
    mesh.remove_vertex(v);
    EXPECT_TRUE(mesh.is_deleted(v));
    EXPECT_FALSE(mesh.find_vertex(p).is_valid());
    EXPECT_EQ(mesh.n_faces(), 15u);
    EXPECT_EQ(mesh.n_edges(), 25u);
    ValidationReport r = validate(mesh, test::open_options());
    EXPECT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r.boundary_loops, 1u);
    for (Vertex w : ring)
        EXPECT_TRUE(mesh.is_boundary(w));
    // Re-insert the node and its fan: the icosahedron again.
    const Vertex nv = mesh.add_vertex(p);
    std::reverse(ring.begin(), ring.end()); // adjacent_vertices is counter-clockwise around v
    for (size_t i = 0; i < ring.size(); ++i)
        mesh.add_triangle(nv, ring[(i + 1) % ring.size()], ring[i]);
    r = validate(mesh);
    EXPECT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r.genus, 0);
}

TEST(MeshSurface, GarbageCollectionCompactsAndRemaps)
{
    ZomeMesh mesh = from_model(fixtures::icosahedron());
    auto tag = mesh.add_vertex_property<int>("v:tag", -1);
    for (Vertex v : vertices(mesh))
        tag[v] = static_cast<int>(v.idx()) * 10;
    mesh.remove_vertex(Vertex(0));
    mesh.remove_vertex(Vertex(7));
    ASSERT_TRUE(mesh.has_garbage());
    const ZomeModel before = to_model(mesh);
    GarbageMap map;
    mesh.garbage_collection(&map);
    EXPECT_FALSE(mesh.has_garbage());
    EXPECT_EQ(mesh.vertices_size(), 10u);
    EXPECT_EQ(map.vertices[0], kInvalidMeshIndex);
    EXPECT_EQ(map.vertices[1], 0u);
    EXPECT_EQ(map.vertices[8], 6u);
    EXPECT_EQ(tag[Vertex(6)], 80);
    EXPECT_EQ(mesh.faces_size(), mesh.n_faces());
    EXPECT_EQ(mesh.edges_size(), mesh.n_edges());
    EXPECT_EQ(to_model(mesh), before);
    const ValidationReport r = validate(mesh, test::open_options());
    EXPECT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(mesh.position_index_size(), 10u);
    for (Vertex v : vertices(mesh))
        EXPECT_EQ(mesh.find_vertex(mesh.position(v)), v);
}

TEST(MeshSurface, ReserveKeepsCapacity)
{
    ZomeMesh mesh = from_model(fixtures::cube_shell(2));
    mesh.reserve(mesh.vertices_size() + 10, mesh.edges_size() + 30, mesh.faces_size() + 20);
    EXPECT_TRUE(mesh.has_capacity_for(10, 30, 20));
    const std::vector<ZVec>* positions = &mesh.positions().vector();
    const ZVec* data = positions->data();
    for (int i = 0; i < 10; ++i)
        mesh.add_vertex(ZVec{{100 + 2 * i, 0, 0, 0, 0, 0}});
    EXPECT_EQ(mesh.positions().vector().data(), data);
    EXPECT_FALSE(mesh.has_capacity_for(1, 0, 0));
}

TEST(MeshSurface, CopyIsDeep)
{
    const ZomeMesh a = from_model(fixtures::torus_shell());
    ZomeMesh b = a;
    b.remove_vertex(Vertex(0));
    EXPECT_TRUE(test::is_valid(a));
    EXPECT_EQ(a.n_vertices(), b.n_vertices() + 1);
    EXPECT_TRUE(a.find_vertex(a.position(Vertex(0))).is_valid());
    EXPECT_FALSE(b.find_vertex(a.position(Vertex(0))).is_valid());
    ZomeMesh c;
    c = b;
    EXPECT_EQ(to_model(c), to_model(b));
    ZomeMesh moved = std::move(c);
    EXPECT_EQ(to_model(moved), to_model(b));
    moved.remove_vertex(Vertex(1));
    EXPECT_TRUE(test::is_valid(moved, test::open_options()));
}
