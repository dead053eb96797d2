#include "core/mesh/circulators.h"

#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "tests/support/zome_fixtures.h"

using namespace zomeify;

TEST(MeshCirculators, AroundVerticesAndFaces)
{
    for (const auto& fx : fixtures::closed_models())
    {
        SCOPED_TRACE(fx.name);
        const ZomeMesh mesh = from_model(fx.model);
        size_t sum_valence = 0;
        for (Vertex v : vertices(mesh))
        {
            size_t n = 0;
            std::set<Vertex> ring;
            for (Halfedge h : outgoing_halfedges(mesh, v))
            {
                EXPECT_EQ(mesh.from_vertex(h), v);
                // Counter-clockwise: the next outgoing halfedge shares the face on h's left.
                EXPECT_EQ(mesh.face(SurfaceMesh::opposite(mesh.ccw_rotated(h))), mesh.face(h));
                ++n;
            }
            for (Vertex w : adjacent_vertices(mesh, v))
            {
                EXPECT_TRUE(mesh.find_halfedge(v, w).is_valid());
                ring.insert(w);
            }
            size_t nf = 0;
            for (Face f : incident_faces(mesh, v))
            {
                const auto corners = face_vertices(mesh, f);
                EXPECT_NE(std::find(corners.begin(), corners.end(), v), corners.end());
                ++nf;
            }
            EXPECT_EQ(n, mesh.valence(v));
            EXPECT_EQ(ring.size(), n);
            EXPECT_EQ(nf, n); // closed surface: one face per outgoing halfedge
            sum_valence += n;
        }
        EXPECT_EQ(sum_valence, 2 * mesh.n_edges());
        size_t fi = 0;
        for (Face f : faces(mesh))
        {
            std::vector<uint32_t> corners;
            for (Vertex w : face_vertices(mesh, f))
                corners.push_back(w.idx());
            // face_vertices starts at the to-vertex of halfedge(f): the model's face rotated by one.
            std::vector<uint32_t> expected = fx.model.faces[fi++];
            std::rotate(expected.begin(), expected.begin() + 1, expected.end());
            EXPECT_EQ(corners, expected);
            size_t nh = 0;
            for (Halfedge h : face_halfedges(mesh, f))
            {
                EXPECT_EQ(mesh.face(h), f);
                ++nh;
            }
            EXPECT_EQ(nh, corners.size());
        }
        size_t n_edges = 0, n_halfedges = 0;
        for (Edge e : edges(mesh))
            n_edges += e.is_valid();
        for (Halfedge h : halfedges(mesh))
            n_halfedges += h.is_valid();
        EXPECT_EQ(n_edges, mesh.n_edges());
        EXPECT_EQ(n_halfedges, mesh.n_halfedges());
    }
}

TEST(MeshCirculators, BoundaryAndIsolatedVertices)
{
    SurfaceMesh m;
    const Vertex a = m.add_vertex(), b = m.add_vertex(), c = m.add_vertex(), d = m.add_vertex();
    const Vertex lonely = m.add_vertex();
    m.add_triangle(a, b, c);
    m.add_triangle(a, c, d);
    size_t n = 0, nf = 0;
    for (Halfedge h : outgoing_halfedges(m, a))
        n += h.is_valid();
    for (Face f : incident_faces(m, a))
        nf += f.is_valid();
    EXPECT_EQ(n, 3u);
    EXPECT_EQ(nf, 2u); // the boundary gap is skipped
    nf = 0;
    for (Face f : incident_faces(m, b))
        nf += f.is_valid();
    EXPECT_EQ(nf, 1u);
    EXPECT_TRUE(m.is_boundary(m.halfedge(b)));
    for (Halfedge h : outgoing_halfedges(m, lonely))
        ADD_FAILURE() << "isolated vertex has " << h;
    for (Face f : incident_faces(m, lonely))
        ADD_FAILURE() << "isolated vertex has " << f;
    // The hole's cycle has the four outer edges.
    size_t hole = 0;
    for (Halfedge h : cycle_halfedges(m, m.halfedge(b)))
        hole += m.is_boundary(h);
    EXPECT_EQ(hole, 4u);
    m.remove_face(Face(0));
    size_t live = 0;
    for (Face f : faces(m))
        live += (f == Face(1));
    EXPECT_EQ(live, 1u);
}
