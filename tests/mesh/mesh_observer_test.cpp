#include "core/mesh/mesh_observer.h"

#include <random>
#include <set>

#include <gtest/gtest.h>

#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/star.h"
#include "core/zome/slots.h"
#include "tests/mesh/mesh_test_util.h"
#include "tests/support/zome_fixtures.h"

using namespace zomeify;

namespace {

// Mirrors the live element sets and a running sum of node positions from the callbacks alone,
// the way an energy cache would, and checks the before/after contract on the way.
class MirrorObserver : public MeshObserver
{
public:
    explicit MirrorObserver(const ZomeMesh& mesh) : m_(mesh)
    {
        for (Vertex v : vertices(mesh))
        {
            vs.insert(v);
            pos_sum += m_.position(v);
        }
        for (Edge e : edges(mesh))
            es.insert(e);
        for (Face f : faces(mesh))
            fs.insert(f);
    }
    void vertex_added(Vertex v) override
    {
        EXPECT_TRUE(vs.insert(v).second);
        pos_sum += m_.position(v);
    }
    void vertex_removing(Vertex v) override
    {
        EXPECT_EQ(vs.erase(v), 1u);
        pos_sum -= m_.position(v);
    }
    void vertex_moving(Vertex v) override { pos_sum -= m_.position(v); }
    void vertex_moved(Vertex v) override { pos_sum += m_.position(v); }
    void edge_added(Edge e) override
    {
        EXPECT_TRUE(es.insert(e).second);
        EXPECT_NE(m_.vector_id(SurfaceMesh::halfedge(e, 0)), kNoZomeVector);
    }
    void edge_removing(Edge e) override
    {
        EXPECT_EQ(es.erase(e), 1u);
        EXPECT_FALSE(m_.is_deleted(e));
    }
    void face_added(Face f) override
    {
        EXPECT_TRUE(fs.insert(f).second);
        EXPECT_GE(m_.valence(f), 3u);
    }
    void face_removing(Face f) override
    {
        EXPECT_EQ(fs.erase(f), 1u);
        EXPECT_FALSE(m_.is_deleted(f));
        EXPECT_GE(m_.valence(f), 3u);
    }
    void compacted(const GarbageMap& map) override
    {
        const auto remap = [](auto& set, const std::vector<MeshIndex>& to) {
            using H = typename std::decay_t<decltype(set)>::value_type;
            std::set<H> out;
            for (H h : set)
                out.insert(H(to[h.idx()]));
            set = std::move(out);
        };
        remap(vs, map.vertices);
        remap(es, map.edges);
        remap(fs, map.faces);
    }

    void expect_matches() const
    {
        std::set<Vertex> v2;
        std::set<Edge> e2;
        std::set<Face> f2;
        ZVec sum;
        for (Vertex v : vertices(m_))
        {
            v2.insert(v);
            sum += m_.position(v);
        }
        for (Edge e : edges(m_))
            e2.insert(e);
        for (Face f : faces(m_))
            f2.insert(f);
        EXPECT_EQ(vs, v2);
        EXPECT_EQ(es, e2);
        EXPECT_EQ(fs, f2);
        EXPECT_EQ(pos_sum, sum);
    }

    std::set<Vertex> vs;
    std::set<Edge> es;
    std::set<Face> fs;
    ZVec pos_sum;

private:
    const ZomeMesh& m_;
};

bool strut_ok(const ZomeMesh& m, Vertex a, Vertex b)
{
    const int s = slot_of(m.position(b) - m.position(a));
    return s >= 0 && !m.find_slot(a, s).is_valid() && !m.find_slot(b, opposite_slot(s)).is_valid() &&
           !m.find_halfedge(a, b).is_valid();
}

} // namespace

TEST(MeshObserver, CallbacksMirrorEveryPrimitive)
{
    ZomeMesh mesh = from_model(fixtures::voxel_surface(fixtures::torus_cells(), fixtures::rhombohedral_basis()));
    MirrorObserver mirror(mesh);
    mesh.set_observer(&mirror);
    std::mt19937 rng(99);
    std::vector<Vertex> link;
    for (int step = 0; step < 1500; ++step)
    {
        const unsigned op = rng() % 4;
        const Face f(static_cast<MeshIndex>(rng() % mesh.faces_size()));
        if (mesh.is_deleted(f))
            continue;
        std::vector<Vertex> c;
        for (Vertex v : face_vertices(mesh, f))
            c.push_back(v);
        if (op == 0 && c.size() == 4 && strut_ok(mesh, c[0], c[2]))
            mesh.split_face(f, c[0], c[2]);
        else if (op == 1 && c.size() == 3)
        {
            const Edge e = SurfaceMesh::edge(mesh.halfedge(f));
            if (mesh.valence(mesh.vertex(e, 0)) >= 4 && mesh.valence(mesh.vertex(e, 1)) >= 4 &&
                mesh.is_remove_edge_ok(e))
                mesh.remove_edge(e);
        }
        else if (op == 2)
        {
            // Remove a node and put it back with its original star.
            const Vertex v = c[0];
            std::vector<std::vector<Vertex>> star;
            for (Face g : incident_faces(mesh, v))
            {
                star.emplace_back();
                for (Vertex w : face_vertices(mesh, g))
                    star.back().push_back(w);
            }
            const ZVec p = mesh.position(v);
            mesh.remove_vertex(v);
            const Vertex nv = mesh.add_vertex(p);
            for (auto& poly : star)
            {
                for (Vertex& w : poly)
                    if (w == v)
                        w = nv;
                mesh.add_face(poly);
            }
        }
        else if (op == 3 && vertex_link(mesh, c[1], link) && is_simple_loop(link))
        {
            // Clear a node's star, move it away and back, refill with the original faces.
            const Vertex v = c[1];
            std::vector<std::vector<Vertex>> star;
            for (Face g : incident_faces(mesh, v))
            {
                star.emplace_back();
                for (Vertex w : face_vertices(mesh, g))
                    star.back().push_back(w);
            }
            const ZVec p = mesh.position(v);
            clear_vertex_star(mesh, v);
            const ZVec away = p + ZVec{{0, 0, 0, 0, 0, 200}};
            mesh.move_vertex(v, away);
            mesh.move_vertex(v, p);
            for (const auto& poly : star)
                mesh.add_face(poly);
        }
        if (step % 500 == 499)
            mesh.garbage_collection();
        ASSERT_TRUE(test::is_valid(mesh)) << "step " << step;
    }
    mirror.expect_matches();
    mesh.set_observer(nullptr);
    const ZomeMesh copy = mesh;
    EXPECT_EQ(copy.observer(), nullptr);
}
