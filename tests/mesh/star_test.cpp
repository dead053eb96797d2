#include "core/mesh/star.h"

#include <optional>

#include <gtest/gtest.h>

#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "core/zome/slots.h"
#include "tests/mesh/mesh_test_util.h"
#include "tests/support/zome_fixtures.h"

using namespace zomeify;

namespace {

struct Centre
{
    ZVec position;
    std::vector<size_t> linked; // indices into the link, ascending
};

// A free position, one Zome vector away from link[anchor], from which every link node it reaches
// gets a strut in a free slot, such that the fan over the link has only triangles and quads and
// every index in `required` is linked (the operators' search, done exhaustively for a test).
std::optional<Centre> find_centre(const ZomeMesh& m, const std::vector<Vertex>& link, size_t anchor,
                                  const std::vector<size_t>& required, const ZVec* avoid)
{
    const size_t n = link.size();
    for (const ZVec& t : zome_vectors())
    {
        const ZVec p = m.position(link[anchor]) + t;
        if (!m.is_position_free(p) || (avoid && p == *avoid))
            continue;
        Centre c{p, {}};
        uint64_t used = 0;
        bool ok = true;
        for (size_t i = 0; i < n && ok; ++i)
        {
            const int s = slot_of(m.position(link[i]) - p);
            if (s < 0)
                continue;
            ok = !(used >> s & 1U) && !m.find_slot(link[i], opposite_slot(s)).is_valid();
            used |= uint64_t{1} << s;
            c.linked.push_back(i);
        }
        for (size_t r : required)
            ok = ok && std::find(c.linked.begin(), c.linked.end(), r) != c.linked.end();
        if (!ok || c.linked.size() < 2)
            continue;
        for (size_t k = 0; k < c.linked.size() && ok; ++k)
            ok = (c.linked[(k + 1) % c.linked.size()] + n - c.linked[k]) % n + 2 <= 4;
        if (ok)
            return c;
    }
    return std::nullopt;
}

void fill_fan(ZomeMesh& m, Vertex centre, const std::vector<Vertex>& link, const std::vector<size_t>& linked)
{
    const size_t n = link.size();
    for (size_t k = 0; k < linked.size(); ++k)
    {
        std::vector<Vertex> poly{centre};
        for (size_t i = linked[k];; i = (i + 1) % n)
        {
            poly.push_back(link[i]);
            if (i == linked[(k + 1) % linked.size()])
                break;
        }
        ASSERT_TRUE(m.add_face(poly).is_valid());
    }
}

ValidateOptions valence2()
{
    ValidateOptions o;
    o.min_valence = 2;
    return o;
}

} // namespace

TEST(MeshStar, VertexAndEdgeLinks)
{
    const ZomeMesh ico = from_model(fixtures::icosahedron());
    std::vector<Vertex> link;
    for (Vertex v : vertices(ico))
    {
        ASSERT_TRUE(vertex_link(ico, v, link));
        EXPECT_EQ(link.size(), 5u);
        EXPECT_TRUE(is_simple_loop(link));
        // Consecutive link nodes are joined by the faces' outer edges, in face orientation.
        for (size_t i = 0; i < link.size(); ++i)
        {
            const Halfedge h = ico.find_halfedge(link[i], link[(i + 1) % link.size()]);
            ASSERT_TRUE(h.is_valid());
            EXPECT_NE(std::find(face_vertices(ico, ico.face(h)).begin(), face_vertices(ico, ico.face(h)).end(), v),
                      face_vertices(ico, ico.face(h)).end());
        }
    }
    const ZomeMesh cube = from_model(fixtures::cube_shell(2));
    for (Edge e : edges(cube))
    {
        ASSERT_TRUE(edge_link(cube, e, link));
        ASSERT_EQ(link.size(), 6u);
        EXPECT_EQ(link[0], cube.vertex(e, 1));
        EXPECT_EQ(link[3], cube.vertex(e, 0));
        EXPECT_TRUE(is_simple_loop(link));
    }
    const Vertex loop[4] = {Vertex(1), Vertex(2), Vertex(3), Vertex(2)};
    EXPECT_FALSE(is_simple_loop(loop));
}

TEST(MeshStar, MoveNodeByClearingAndRefillingItsStar)
{
    // MOVNODE: clear the star, move the node, connect it to every link node it reaches.
    for (const char* name : {"icosahedron", "rhombo_block_2", "rhombo_torus"})
    {
        SCOPED_TRACE(name);
        ZomeMesh mesh;
        int genus = 0;
        for (auto& fx : fixtures::closed_models())
            if (fx.name == name)
            {
                mesh = from_model(fx.model);
                genus = fx.genus;
            }
        size_t moved = 0;
        std::vector<Vertex> link;
        for (Vertex v : vertices(mesh))
        {
            ASSERT_TRUE(vertex_link(mesh, v, link));
            if (!is_simple_loop(link))
                continue;
            const ZVec old = mesh.position(v);
            const size_t nv = mesh.n_vertices();
            const ZomeMesh backup = mesh;
            clear_vertex_star(mesh, v);
            ASSERT_TRUE(mesh.is_isolated(v));
            const auto centre = find_centre(mesh, link, moved % link.size(), {}, &old);
            if (!centre)
            {
                mesh = backup; // no valid new position for this node: undo the clearing
                continue;
            }
            mesh.move_vertex(v, centre->position);
            fill_fan(mesh, v, link, centre->linked);

            const ValidationReport r = validate(mesh, valence2());
            ASSERT_TRUE(r.ok()) << r.message();
            ASSERT_EQ(r.genus, genus);
            EXPECT_EQ(mesh.n_vertices(), nv);
            EXPECT_FALSE(mesh.find_vertex(old).is_valid());
            if (++moved == 5)
                break;
        }
        EXPECT_GT(moved, 0u);
    }
}

TEST(MeshStar, SplitStrutByClearingItsStar)
{
    // SPLITSTRUT: clear the two faces of a strut; the new node links at least to both ends.
    ZomeMesh mesh = from_model(fixtures::voxel_surface(fixtures::block_cells(2, 2, 1), fixtures::rhombohedral_basis()));
    std::vector<Vertex> link;
    size_t splits = 0;
    for (Edge e : edges(mesh))
    {
        if (mesh.is_deleted(e) || !edge_link(mesh, e, link) || !is_simple_loop(link))
            continue;
        const size_t mid = link.size() / 2; // link[0] and link[mid] are the strut's ends
        ZomeMesh trial = mesh;
        clear_edge_star(trial, e);
        EXPECT_TRUE(trial.is_deleted(e));
        const auto centre = find_centre(trial, link, 0, {0, mid}, nullptr);
        if (!centre)
            continue;
        const Vertex c = trial.add_vertex(centre->position);
        fill_fan(trial, c, link, centre->linked);
        const ValidationReport r = validate(trial, valence2());
        ASSERT_TRUE(r.ok()) << r.message();
        EXPECT_EQ(r.genus, 0);
        EXPECT_EQ(trial.n_vertices(), mesh.n_vertices() + 1);
        mesh = trial;
        if (++splits == 5)
            break;
    }
    EXPECT_GT(splits, 0u);
}
