// Local edits on Zome meshes, in the shape the annealer's operators use them (paper §3.2, §5.1):
// diagonal add/remove/flip, node insertion into a face and node removal, each followed by validate().

#include <random>

#include <gtest/gtest.h>

#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/topology_error.h"
#include "core/zome/slots.h"
#include "tests/mesh/mesh_test_util.h"
#include "tests/support/zome_fixtures.h"

using namespace zomeify;

namespace {

// Whether a strut a→b would be a Zome vector in free slots at both ends (and not a second a–b edge).
bool strut_ok(const ZomeMesh& m, Vertex a, Vertex b)
{
    const int s = slot_of(m.position(b) - m.position(a));
    return s >= 0 && !m.find_slot(a, s).is_valid() && !m.find_slot(b, opposite_slot(s)).is_valid() &&
           !m.find_halfedge(a, b).is_valid();
}

std::vector<Vertex> corners_of(const ZomeMesh& m, Face f)
{
    std::vector<Vertex> out;
    for (Vertex v : face_vertices(m, f))
        out.push_back(v);
    return out;
}

ZomeMesh rhombo_block()
{
    return from_model(fixtures::voxel_surface(fixtures::block_cells(2, 2, 2), fixtures::rhombohedral_basis()));
}

} // namespace

TEST(MeshZome, PositionsSlotsAndIndex)
{
    ZomeMesh mesh = from_model(fixtures::cube_shell(1));
    for (Halfedge h : halfedges(mesh))
    {
        EXPECT_EQ(mesh.slot(h), slot_of(mesh.vector(h)));
        EXPECT_EQ(mesh.slot(SurfaceMesh::opposite(h)), opposite_slot(mesh.slot(h)));
        EXPECT_EQ(mesh.kind(SurfaceMesh::edge(h)), StrutKind::B1);
    }
    for (Vertex v : vertices(mesh))
    {
        EXPECT_EQ(mesh.find_vertex(mesh.position(v)), v);
        for (Halfedge h : outgoing_halfedges(mesh, v))
            EXPECT_EQ(mesh.find_slot(v, mesh.slot(h)), h);
    }
    for (Edge e : edges(mesh))
        EXPECT_FALSE(mesh.is_new_strut_ok(mesh.vertex(e, 0), mesh.vertex(e, 1))); // already joined
    for (Vertex v : vertices(mesh))
        for (Halfedge h : outgoing_halfedges(mesh, v))
            EXPECT_FALSE(mesh.is_slot_free(v, mesh.slot(h)));
    // A node one b1 beyond a corner along +x reaches that corner if its −x slot is free there.
    const Vertex corner = mesh.find_vertex(ZVec{{2, 0, 0, 0, 0, 0}});
    ASSERT_TRUE(corner.is_valid());
    const ZVec beyond{{4, 0, 0, 0, 0, 0}};
    EXPECT_EQ(mesh.new_strut_id(beyond, corner), vector_id_of(ZVec{{-2, 0, 0, 0, 0, 0}}));
    // From p = (−1, 0, 0) the strut would be a B2 in the corner's −x slot, which already holds
    // its strut to the origin.
    const ZVec behind{{0, -2, 0, 0, 0, 0}};
    EXPECT_GE(vector_id_of(mesh.position(corner) - behind), 0);
    EXPECT_EQ(mesh.new_strut_id(behind, corner), -1);
    EXPECT_EQ(mesh.new_strut_id(beyond, mesh.find_vertex(ZVec{})), -1); // (−2φ, 0, 0) is no strut
    EXPECT_EQ(mesh.new_strut_id(ZVec{{1, 0, 1, 0, 0, 0}}, corner), -1); // not a Zome vector
    EXPECT_THROW(mesh.add_vertex(mesh.position(Vertex(2))), TopologyError);
    EXPECT_FALSE(mesh.is_position_free(mesh.position(Vertex(2))));
    EXPECT_FALSE(mesh.find_vertex(ZVec{{50, 0, 0, 0, 0, 0}}).is_valid());
}

TEST(MeshZome, MoveVertexUpdatesIndexAndSlots)
{
    // Stretch the cube: move the four nodes of the x = φ side to x = φ².
    ZomeMesh mesh = from_model(fixtures::cube_shell(1));
    std::vector<Vertex> side;
    for (Vertex v : vertices(mesh))
        if (mesh.position(v).c[0] == 2)
            side.push_back(v);
    ASSERT_EQ(side.size(), 4u);
    for (Vertex v : side)
    {
        const ZVec old = mesh.position(v);
        mesh.move_vertex(v, old + ZVec{{0, 2, 0, 0, 0, 0}}); // + b0 along x: φ + 1 = φ²
        EXPECT_TRUE(mesh.is_position_free(old));
        EXPECT_EQ(mesh.find_vertex(mesh.position(v)), v);
    }
    const ValidationReport r = validate(mesh);
    EXPECT_TRUE(r.ok()) << r.message();
    size_t b0 = 0, b1 = 0, b2 = 0;
    for (Edge e : edges(mesh))
    {
        b0 += mesh.kind(e) == StrutKind::B0;
        b1 += mesh.kind(e) == StrutKind::B1;
        b2 += mesh.kind(e) == StrutKind::B2;
    }
    EXPECT_EQ(b1, 8u);
    EXPECT_EQ(b2, 4u); // φ + 1 = φ²
    EXPECT_EQ(b0, 0u);
    EXPECT_THROW(mesh.move_vertex(side[0], mesh.position(side[1])), TopologyError);
}

TEST(MeshZome, SplitQuadByDiagonalAndMergeBack)
{
    ZomeMesh mesh = rhombo_block();
    const ZomeModel original = to_model(mesh);
    size_t done = 0;
    for (Face f : faces(mesh))
    {
        const std::vector<Vertex> c = corners_of(mesh, f);
        ASSERT_EQ(c.size(), 4u);
        Face quad = f; // merging keeps one of the two triangles' handles
        for (int k = 0; k < 2; ++k)
        {
            const Vertex a = c[k], b = c[k + 2];
            ASSERT_TRUE(mesh.is_zome_pair(a, b)); // the rhombohedral lattice's promise
            if (!strut_ok(mesh, a, b))
                continue;
            const size_t nf = mesh.n_faces(), ne = mesh.n_edges();
            const Halfedge d = mesh.split_face(quad, a, b);
            EXPECT_EQ(mesh.n_faces(), nf + 1);
            EXPECT_EQ(mesh.n_edges(), ne + 1);
            EXPECT_EQ(mesh.slot(d), slot_of(mesh.position(b) - mesh.position(a)));
            ValidationReport r = validate(mesh);
            ASSERT_TRUE(r.ok()) << r.message();
            EXPECT_EQ(r.genus, 0);
            ASSERT_TRUE(mesh.is_remove_edge_ok(SurfaceMesh::edge(d)));
            quad = mesh.remove_edge(SurfaceMesh::edge(d));
            EXPECT_EQ(mesh.valence(quad), 4u);
            r = validate(mesh);
            ASSERT_TRUE(r.ok()) << r.message();
            ++done;
        }
    }
    EXPECT_GT(done, 0u);
    mesh.garbage_collection();
    const ZomeModel after = to_model(mesh);
    EXPECT_EQ(after.nodes, original.nodes);
    EXPECT_EQ(after.struts.size(), original.struts.size());
    EXPECT_EQ(after.faces.size(), original.faces.size());
}

TEST(MeshZome, InsertNodeInFaceAndRemoveIt)
{
    for (const char* name : {"rhombo_block_2", "icosahedron"})
    {
        SCOPED_TRACE(name);
        ZomeMesh mesh;
        for (auto& fx : fixtures::closed_models())
            if (fx.name == name)
                mesh = from_model(fx.model);
        const size_t nv = mesh.n_vertices(), ne = mesh.n_edges(), nf = mesh.n_faces();
        bool inserted = false;
        for (Face f : faces(mesh))
        {
            const std::vector<Vertex> c = corners_of(mesh, f);
            const size_t n = c.size();
            for (const ZVec& t : zome_vectors())
            {
                // A node p one strut away from corner 0, linked to every corner it reaches.
                const ZVec p = mesh.position(c[0]) + t;
                if (!mesh.is_position_free(p))
                    continue;
                std::vector<size_t> linked;
                uint64_t slots_at_p = 0;
                bool ok = true;
                for (size_t i = 0; i < n && ok; ++i)
                {
                    const int s = slot_of(mesh.position(c[i]) - p);
                    if (s < 0)
                        continue;
                    ok = !(slots_at_p >> s & 1U) && !mesh.find_slot(c[i], opposite_slot(s)).is_valid();
                    slots_at_p |= uint64_t{1} << s;
                    linked.push_back(i);
                }
                if (!ok || linked.size() < 2)
                    continue;
                // Faces p, c[i], ..., c[j] between consecutive linked corners must have ≤ 4 corners.
                for (size_t k = 0; k < linked.size() && ok; ++k)
                {
                    const size_t gap = (linked[(k + 1) % linked.size()] + n - linked[k]) % n;
                    ok = gap + 2 <= 4;
                }
                if (!ok)
                    continue;
                mesh.remove_face(f);
                const Vertex v = mesh.add_vertex(p);
                for (size_t k = 0; k < linked.size(); ++k)
                {
                    std::vector<Vertex> poly{v};
                    for (size_t i = linked[k];; i = (i + 1) % n)
                    {
                        poly.push_back(c[i]);
                        if (i == linked[(k + 1) % linked.size()])
                            break;
                    }
                    ASSERT_TRUE(mesh.add_face(poly).is_valid());
                }
                ValidateOptions o;
                o.min_valence = 2; // a node linked to two corners of a quad has valence 2
                ValidationReport r = validate(mesh, o);
                ASSERT_TRUE(r.ok()) << r.message();
                EXPECT_EQ(r.genus, 0);
                EXPECT_EQ(mesh.n_vertices(), nv + 1);
                // Remove it again and refill the link with the original face.
                mesh.remove_vertex(v);
                ASSERT_TRUE(mesh.add_face(c).is_valid());
                r = validate(mesh);
                ASSERT_TRUE(r.ok()) << r.message();
                EXPECT_EQ(mesh.n_vertices(), nv);
                EXPECT_EQ(mesh.n_edges(), ne);
                EXPECT_EQ(mesh.n_faces(), nf);
                inserted = true;
                break;
            }
            if (inserted)
                break;
        }
        EXPECT_TRUE(inserted);
    }
}

TEST(MeshZome, RandomDiagonalEditsKeepEveryInvariant)
{
    std::mt19937 rng(20261123);
    for (const char* name : {"rhombo_block_2", "rhombo_torus", "rhombo_double_torus"})
    {
        SCOPED_TRACE(name);
        ZomeMesh mesh;
        int genus = -1;
        for (auto& fx : fixtures::closed_models())
            if (fx.name == name)
            {
                mesh = from_model(fx.model);
                genus = fx.genus;
            }
        size_t adds = 0, removes = 0, flips = 0;
        for (int step = 0; step < 3000; ++step)
        {
            const Face f(static_cast<MeshIndex>(rng() % mesh.faces_size()));
            if (mesh.is_deleted(f))
                continue;
            const std::vector<Vertex> c = corners_of(mesh, f);
            if (c.size() == 4)
            {
                const size_t k = rng() % 2;
                if (!strut_ok(mesh, c[k], c[k + 2]))
                    continue;
                mesh.split_face(f, c[k], c[k + 2]);
                ++adds;
            }
            else
            {
                Halfedge h = mesh.halfedge(f);
                for (unsigned i = rng() % 3; i > 0; --i)
                    h = mesh.next(h);
                const Halfedge o = SurfaceMesh::opposite(h);
                if (mesh.valence(mesh.face(o)) != 3)
                    continue;
                // Keep valence ≥ 3 at the diagonal's ends (the annealer's rule for closed surfaces).
                const Vertex a = mesh.from_vertex(h), b = mesh.to_vertex(h);
                if (mesh.valence(a) < 4 || mesh.valence(b) < 4)
                    continue;
                const Vertex x = mesh.to_vertex(mesh.next(h)), y = mesh.to_vertex(mesh.next(o));
                const bool flip = rng() % 2 == 0;
                if (flip && !strut_ok(mesh, x, y))
                    continue;
                const Face merged = mesh.remove_edge(SurfaceMesh::edge(h));
                if (flip)
                {
                    mesh.split_face(merged, x, y);
                    ++flips;
                }
                else
                    ++removes;
            }
            const ValidationReport r = validate(mesh);
            ASSERT_TRUE(r.ok()) << "step " << step << ": " << r.message();
            ASSERT_EQ(r.genus, genus);
            if (step % 700 == 699)
            {
                mesh.garbage_collection();
                ASSERT_TRUE(test::is_valid(mesh));
            }
        }
        EXPECT_GT(adds, 50u);
        EXPECT_GT(removes, 20u);
        EXPECT_GT(flips, 5u);
        // A round trip through the model keeps the edited surface.
        const ZomeModel model = to_model(mesh);
        const ZomeMesh again = from_model(model);
        EXPECT_TRUE(test::is_valid(again));
        const ZomeModel back = to_model(again);
        EXPECT_EQ(back.nodes, model.nodes);
        EXPECT_EQ(back.faces, model.faces);
        EXPECT_EQ(back.struts.size(), model.struts.size());
    }
}
