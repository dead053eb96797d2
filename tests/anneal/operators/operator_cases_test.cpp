// The seven operators on small exact fixtures (paper §3.2, §5.1; design §3.4): hand-checked
// results, and each validity rule refusing a crafted bad case.
#include <algorithm>

#include <gtest/gtest.h>

#include "core/anneal/operators/operators.h"
#include "core/mesh/circulators.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/star.h"
#include "core/mesh/validate.h"
#include "tests/anneal/operators/operator_test_support.h"
#include "tests/support/zome_fixtures.h"

namespace zomeify {
namespace {

using detail::Fill;

// Runs one explicit-element operator and, when valid, applies it.
struct Outcome
{
    Rejection rejection = Rejection::None;
    Proposal proposal;
};

template <class Op>
Outcome run(ZomeMesh& mesh, Op op, bool apply = true)
{
    Outcome out;
    Claims claims;
    Fill fill;
    out.rejection = op(claims, fill, out.proposal.change);
    out.proposal.rejection = out.rejection;
    if (out.rejection == Rejection::None)
    {
        EXPECT_EQ(check_change(mesh, out.proposal.change), "");
        if (apply)
            apply_proposal(mesh, out.proposal);
    }
    return out;
}

void expect_valid(const ZomeMesh& mesh, int genus)
{
    const ValidationReport report = validate(mesh);
    EXPECT_TRUE(report.ok()) << report.message();
    EXPECT_EQ(report.genus, genus);
}

Vertex node_at(const ZomeMesh& mesh, const ZVec& p)
{
    const Vertex v = mesh.find_vertex(p);
    EXPECT_TRUE(v.is_valid());
    return v;
}

Face first_face(const ZomeMesh& mesh)
{
    for (MeshIndex i = 0;; ++i)
        if (mesh.is_valid(Face(i)))
            return Face(i);
}

std::vector<ZVec> corners(const ZomeMesh& mesh, Face f)
{
    std::vector<ZVec> c;
    for (Vertex v : face_vertices(mesh, f))
        c.push_back(mesh.position(v));
    return c;
}

TEST(Operators, NamesArePapers)
{
    EXPECT_EQ(operator_name(OperatorKind::InsNode), "INSNODE");
    EXPECT_EQ(operator_name(OperatorKind::SplitStrut), "SPLITSTRUT");
    EXPECT_EQ(operator_name(OperatorKind::RemNode), "REMNODE");
    for (int r = 0; r < kRejectionKinds; ++r)
        EXPECT_NE(rejection_name(static_cast<Rejection>(r)), "?");
}

TEST(Operators, AddDiagRemDiagFlipDiagOnARhombus)
{
    const ZomeModel cell = test::rhombic_cell();
    ZomeMesh mesh = from_model(cell);
    const auto original = test::face_set(mesh);
    const Face f = first_face(mesh);
    const std::vector<ZVec> q = corners(mesh, f);
    ASSERT_EQ(q.size(), 4u);

    // ADDDIAG from corner 0: q0–q2, faces (q0, q1, q2) and (q2, q3, q0).
    Outcome add =
        run(mesh, [&](Claims& c, Fill& fill, LocalChange& ch) { return detail::add_diag_at(mesh, f, 0, c, fill, ch); });
    ASSERT_EQ(add.rejection, Rejection::None);
    expect_valid(mesh, 0);
    EXPECT_EQ(mesh.n_faces(), 7u);
    EXPECT_EQ(mesh.n_edges(), 13u);
    const Halfedge diag = mesh.find_halfedge(node_at(mesh, q[0]), node_at(mesh, q[2]));
    ASSERT_TRUE(diag.is_valid());
    auto rotated = [](std::vector<ZVec> c) {
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        return c;
    };
    auto expected = original;
    expected.erase(std::find(expected.begin(), expected.end(), rotated(q)));
    auto with_triangles = expected;
    with_triangles.push_back(rotated({q[0], q[1], q[2]}));
    with_triangles.push_back(rotated({q[2], q[3], q[0]}));
    std::sort(with_triangles.begin(), with_triangles.end());
    EXPECT_EQ(test::face_set(mesh), with_triangles);

    // FLIPDIAG of q0–q2 gives q1–q3: faces (q1, q2, q3) and (q3, q0, q1).
    Outcome flip = run(
        mesh, [&](Claims& c, Fill& fill, LocalChange& ch) { return detail::flip_diag_at(mesh, diag, c, fill, ch); });
    ASSERT_EQ(flip.rejection, Rejection::None);
    expect_valid(mesh, 0);
    EXPECT_FALSE(mesh.find_edge(node_at(mesh, q[0]), node_at(mesh, q[2])).is_valid());
    const Halfedge other = mesh.find_halfedge(node_at(mesh, q[1]), node_at(mesh, q[3]));
    ASSERT_TRUE(other.is_valid());
    auto flipped = expected;
    flipped.push_back(rotated({q[1], q[2], q[3]}));
    flipped.push_back(rotated({q[3], q[0], q[1]}));
    std::sort(flipped.begin(), flipped.end());
    EXPECT_EQ(test::face_set(mesh), flipped);

    // REMDIAG of q1–q3 restores the rhombus.
    Outcome rem = run(
        mesh, [&](Claims& c, Fill& fill, LocalChange& ch) { return detail::rem_diag_at(mesh, other, c, fill, ch); });
    ASSERT_EQ(rem.rejection, Rejection::None);
    expect_valid(mesh, 0);
    EXPECT_EQ(test::face_set(mesh), original);
}

TEST(Operators, AddDiagRefusesADiagonalThatIsNoZomeVector)
{
    // The diagonal of a B1 square, (φ, φ, 0), is no Zome vector.
    ZomeMesh mesh = from_model(fixtures::cube_shell(1));
    const Face f = first_face(mesh);
    for (size_t corner = 0; corner < 2; ++corner)
    {
        const Outcome out = run(mesh, [&](Claims& c, Fill& fill, LocalChange& ch) {
            return detail::add_diag_at(mesh, f, corner, c, fill, ch);
        });
        EXPECT_EQ(out.rejection, Rejection::NoCandidate);
    }
}

TEST(Operators, RemDiagRefusesATriangleNextToAQuad)
{
    ZomeMesh mesh = from_model(test::rhombic_cell());
    const Face f = first_face(mesh);
    const std::vector<ZVec> q = corners(mesh, f);
    run(mesh, [&](Claims& c, Fill& fill, LocalChange& ch) { return detail::add_diag_at(mesh, f, 0, c, fill, ch); });
    // q0–q1 has the triangle (q0, q1, q2) on one side and a rhombus on the other: 5 corners.
    const Halfedge h = mesh.find_halfedge(node_at(mesh, q[0]), node_at(mesh, q[1]));
    const Outcome out =
        run(mesh, [&](Claims& c, Fill& fill, LocalChange& ch) { return detail::rem_diag_at(mesh, h, c, fill, ch); });
    EXPECT_EQ(out.rejection, Rejection::FaceSize);
}

TEST(Operators, TetrahedronRefusesDoubleStrutsAndLowValence)
{
    ZomeMesh mesh = from_model(test::zome_tetrahedron());
    expect_valid(mesh, 0);
    const Halfedge h = ZomeMesh::halfedge(Edge(0), 0);
    // FLIPDIAG: the other two nodes are already joined.
    Outcome flip =
        run(mesh, [&](Claims& c, Fill& fill, LocalChange& ch) { return detail::flip_diag_at(mesh, h, c, fill, ch); });
    EXPECT_EQ(flip.rejection, Rejection::DoubleStrut);
    // REMDIAG: both ends would keep two struts.
    Outcome rem =
        run(mesh, [&](Claims& c, Fill& fill, LocalChange& ch) { return detail::rem_diag_at(mesh, h, c, fill, ch); });
    EXPECT_EQ(rem.rejection, Rejection::Valence);
    // REMNODE: the remaining triangle's corners would keep two struts each.
    Rng rng(1);
    Proposal p;
    EXPECT_FALSE(test::propose_at(OperatorKind::RemNode, mesh, Vertex(0), rng, p));
    EXPECT_EQ(p.rejection, Rejection::Valence);
}

TEST(Operators, InsNodeRefusesTwoLinkNodesInOneDirection)
{
    // On a rhombus (q0, q1, q2, q3) with a Zome diagonal d = q2 − q0 of size 0 or 1, a node p on
    // the diagonal's line beyond q0 sees q0 and q2 in one direction, at sizes s and s + 2: one
    // slot of p for two struts. (Neighbouring link nodes cannot show this: their link edge takes
    // the slot first.)
    ZomeMesh mesh = from_model(test::rhombic_cell());
    const Face f = first_face(mesh);
    const std::vector<ZVec> q = corners(mesh, f);
    int tried = 0;
    for (size_t a = 0; a < 2; ++a)
    {
        const ZVec d = q[a + 2] - q[a];
        const int id = vector_id_of(d);
        ASSERT_GE(id, 0);
        if (vector_size(id) == 2)
            continue;
        const ZVec p = vector_size(id) == 0 ? q[a] - d.times_phi() : q[a] - d.div_phi();
        const Outcome out = run(
            mesh, [&](Claims& c, Fill& fill, LocalChange& ch) { return detail::ins_node_at(mesh, f, p, c, fill, ch); });
        EXPECT_EQ(out.rejection, Rejection::SlotConflict);
        ++tried;
    }
    EXPECT_GT(tried, 0);
}

TEST(Operators, NewNodesNeedFreePositions)
{
    ZomeMesh mesh = from_model(fixtures::icosahedron());
    const Face f = first_face(mesh);
    const Vertex other = Vertex(5);
    Outcome ins = run(mesh, [&](Claims& c, Fill& fill, LocalChange& ch) {
        return detail::ins_node_at(mesh, f, mesh.position(other), c, fill, ch);
    });
    EXPECT_EQ(ins.rejection, Rejection::Occupied);
    Outcome mov = run(mesh, [&](Claims& c, Fill& fill, LocalChange& ch) {
        return detail::mov_node_to(mesh, Vertex(0), mesh.position(other), c, fill, ch);
    });
    EXPECT_EQ(mov.rejection, Rejection::Occupied);
}

TEST(Operators, InsNodeAtTheIcosahedronCentreConnectsAllThreeCorners)
{
    // The icosahedron's nodes are R0 vectors from the origin: a node there reaches every corner.
    ZomeMesh mesh = from_model(fixtures::icosahedron());
    const Face f = first_face(mesh);
    const std::vector<ZVec> t = corners(mesh, f);
    // The origin is inside the solid, but the operator only sees the face's link: three new
    // triangles (o, a, b), (o, b, c), (o, c, a) replace (a, b, c).
    const Outcome out = run(mesh, [&](Claims& c, Fill& fill, LocalChange& ch) {
        return detail::ins_node_at(mesh, f, ZVec{}, c, fill, ch);
    });
    ASSERT_EQ(out.rejection, Rejection::None);
    expect_valid(mesh, 0);
    EXPECT_EQ(mesh.n_vertices(), 13u);
    EXPECT_EQ(mesh.n_faces(), 22u);
    const Vertex o = node_at(mesh, ZVec{});
    EXPECT_EQ(mesh.valence(o), 3u);
    for (const ZVec& corner : t)
    {
        const Halfedge h = mesh.find_halfedge(o, node_at(mesh, corner));
        ASSERT_TRUE(h.is_valid());
        EXPECT_EQ(mesh.kind(ZomeMesh::edge(h)), StrutKind::R0);
    }

    // REMNODE of it restores the icosahedron (a triangle link is filled by one face).
    Rng rng(3);
    Proposal p;
    ASSERT_TRUE(test::propose_at(OperatorKind::RemNode, mesh, o, rng, p));
    apply_proposal(mesh, p);
    expect_valid(mesh, 0);
    EXPECT_EQ(test::face_set(mesh), test::face_set(from_model(fixtures::icosahedron())));
}

TEST(Operators, SplitStrutAtTheCentreThenRemNode)
{
    // SPLITSTRUT of an icosahedron edge a → b (b0) at the centre o: a → b = (o − a) + (b − o),
    // two R0 struts, and o also reaches the two other corners of the strut's triangles (R0).
    ZomeMesh mesh = from_model(fixtures::icosahedron());
    const Halfedge h = ZomeMesh::halfedge(Edge(0), 0);
    const ZVec a = mesh.position(mesh.from_vertex(h)), b = mesh.position(mesh.to_vertex(h));
    const Outcome out = run(mesh, [&](Claims& c, Fill& fill, LocalChange& ch) {
        return detail::split_strut_at(mesh, h, ZVec{}, c, fill, ch);
    });
    ASSERT_EQ(out.rejection, Rejection::None);
    expect_valid(mesh, 0);
    EXPECT_EQ(mesh.n_vertices(), 13u);
    EXPECT_EQ(mesh.n_faces(), 22u); // two triangles replaced by four
    EXPECT_FALSE(mesh.find_edge(node_at(mesh, a), node_at(mesh, b)).is_valid());
    const Vertex o = node_at(mesh, ZVec{});
    EXPECT_EQ(mesh.valence(o), 4u);

    // REMNODE of o: its quad link is filled by one quad or two triangles.
    Rng rng(11);
    Proposal p;
    bool removed = false;
    for (int i = 0; i < 50 && !removed; ++i)
        removed = test::propose_at(OperatorKind::RemNode, mesh, o, rng, p);
    ASSERT_TRUE(removed);
    apply_proposal(mesh, p);
    expect_valid(mesh, 0);
    EXPECT_EQ(mesh.n_vertices(), 12u);
}

TEST(Operators, MovNodeOnACubeShellStaysValid)
{
    // Every valid MOVNODE of a face-centre node of a 2×2×2 B1 cube shell gives a valid mesh, and
    // the node ends at the proposed position with struts to the link only.
    const ZomeModel model = fixtures::cube_shell(2);
    int applied = 0;
    for (uint64_t seed = 0; seed < 400 && applied < 20; ++seed)
    {
        ZomeMesh mesh = from_model(model);
        Rng rng(seed);
        const Vertex n = test::random_node(mesh, rng);
        Proposal p;
        if (!test::propose_at(OperatorKind::MovNode, mesh, n, rng, p))
            continue;
        ASSERT_EQ(check_change(mesh, p.change), "");
        const ZVec target = p.change.added_nodes()[0];
        apply_proposal(mesh, p);
        expect_valid(mesh, 0);
        EXPECT_EQ(mesh.find_vertex(target), n); // the handle is kept
        ++applied;
    }
    EXPECT_GT(applied, 0);
}

TEST(Operators, RemNodeRefusesALinkNoZomeChordsCanFill)
{
    // A corner of a B1 cube: its link is a hexagon (three squares) whose chords are all square
    // diagonals or (±φ, ±φ, ±φ)-like vectors, none of them Zome vectors.
    ZomeMesh mesh = from_model(fixtures::cube_shell(1));
    for (uint64_t seed = 0; seed < 8; ++seed)
    {
        Rng rng(seed);
        Proposal p;
        EXPECT_FALSE(test::propose_at(OperatorKind::RemNode, mesh, Vertex(static_cast<MeshIndex>(seed)), rng, p));
        EXPECT_EQ(p.rejection, Rejection::NoCandidate);
    }
}

TEST(Operators, ProposalsClaimEverythingTheEnergyReads)
{
    // The claiming rule of proposal.h: every node of the removed region, every surviving end of a
    // removed or added strut, and every neighbour of those ends (E_fair reads their positions).
    ZomeMesh mesh = from_model(fixtures::double_torus_shell());
    Rng rng(2026);
    Proposal p;
    int checked = 0;
    for (int step = 0; step < 20000; ++step)
    {
        auto kind = static_cast<OperatorKind>(rng.below(kOperatorKinds));
        if (mesh.n_vertices() > 100 && (kind == OperatorKind::InsNode || kind == OperatorKind::SplitStrut))
            kind = OperatorKind::RemNode; // keep the model small
        Claims claims;
        const Vertex seed = test::random_node(mesh, rng);
        claims.take(seed);
        if (!propose(kind, mesh, seed, rng, claims, p))
            continue;
        const LocalChange& c = p.change;
        std::vector<Vertex> ends;
        for (Face f : c.removed_faces())
            for (Vertex v : face_vertices(mesh, f))
                EXPECT_TRUE(claims.holds(v)) << operator_name(kind);
        for (Vertex v : c.removed_nodes())
            EXPECT_TRUE(claims.holds(v)) << operator_name(kind);
        for (Edge e : c.removed_struts())
            for (int i = 0; i < 2; ++i)
                ends.push_back(mesh.vertex(e, i));
        for (const NewStrut& s : c.added_struts())
            for (const ZVec& q : {s.a, s.b})
                if (const Vertex v = mesh.find_vertex(q); v.is_valid())
                    ends.push_back(v);
        for (Vertex v : ends)
        {
            if (std::find(c.removed_nodes().begin(), c.removed_nodes().end(), v) != c.removed_nodes().end())
                continue;
            EXPECT_TRUE(claims.holds(v)) << operator_name(kind);
            for (Vertex w : adjacent_vertices(mesh, v))
                EXPECT_TRUE(claims.holds(w)) << operator_name(kind) << ": neighbour of a changed node";
        }
        apply_proposal(mesh, p);
        ++checked;
    }
    EXPECT_GT(checked, 1000);
}

TEST(Operators, LinksThatVisitANodeTwiceAreRefused)
{
    // On meshes shaped by random applications, REMNODE says LinkTwice exactly when star.h's vertex
    // link is not a simple loop, and SPLITSTRUT exactly when the strut's link is not. A strut's link
    // can only visit a node twice through a folded quad (a quad whose diagonal is a strut) or a
    // node of valence 2, and the operators allow neither, so no strut link here is non-simple.
    ZomeMesh mesh = from_model(fixtures::double_torus_shell());
    Rng rng(77);
    Proposal p;
    std::vector<Vertex> link;
    int twice_nodes = 0, twice_struts = 0;
    for (int round = 0; round < 40; ++round)
    {
        for (int applied = 0; applied < 50;)
        {
            const auto kind = static_cast<OperatorKind>(rng.below(kOperatorKinds));
            if (test::propose_at(kind, mesh, test::random_node(mesh, rng), rng, p))
            {
                apply_proposal(mesh, p);
                ++applied;
            }
        }
        for (MeshIndex i = 0; i < mesh.vertices_size(); ++i)
        {
            const Vertex v(i);
            if (!mesh.is_valid(v))
                continue;
            ASSERT_TRUE(vertex_link(mesh, v, link));
            const bool simple = is_simple_loop(link);
            test::propose_at(OperatorKind::RemNode, mesh, v, rng, p);
            EXPECT_EQ(p.rejection == Rejection::LinkTwice, !simple);
            twice_nodes += simple ? 0 : 1;
        }
        for (MeshIndex e = 0; e < mesh.edges_size(); ++e)
        {
            if (!mesh.is_valid(Edge(e)))
                continue;
            ASSERT_TRUE(edge_link(mesh, Edge(e), link));
            const bool simple = is_simple_loop(link);
            const Outcome out = run(
                mesh,
                [&](Claims& c, Fill& fill, LocalChange& ch) {
                    return detail::split_strut_at(mesh, ZomeMesh::halfedge(Edge(e), 0), ZVec{}, c, fill, ch);
                },
                /*apply=*/false);
            EXPECT_EQ(out.rejection == Rejection::LinkTwice, !simple);
            twice_struts += simple ? 0 : 1;
        }
    }
    EXPECT_GT(twice_nodes, 0);
    EXPECT_EQ(twice_struts, 0);
}

} // namespace
} // namespace zomeify
