// Incremental energy (design §3.3): for many random local edits on the closed fixtures, the ΔE
// simulated from the change alone equals the change of a full recomputation, and after each commit
// the state's sums equal those of a fresh evaluate_energy, bit for bit.
#include <cmath>
#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/anneal/energy_state.h"
#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "core/zome/slots.h"
#include "tests/anneal/energy_test_support.h"
#include "tests/support/zome_fixtures.h"

namespace zomeify {
namespace {

using Rng = std::mt19937;

// One proposal: the energy's description and the mesh edit that realises it.
struct Edit
{
    const char* kind = "";
    LocalChange change;
    std::function<void(ZomeMesh&)> apply;
};

template <class H>
H random_element(const ZomeMesh& mesh, size_t size, Rng& rng)
{
    std::uniform_int_distribution<MeshIndex> pick(0, static_cast<MeshIndex>(size - 1));
    for (int tries = 0; tries < 64; ++tries)
    {
        const H h(pick(rng));
        if (!mesh.is_deleted(h))
        {
            return h;
        }
    }
    return H();
}

std::vector<Vertex> corners_of(const ZomeMesh& mesh, Face f)
{
    std::vector<Vertex> out;
    for (Vertex v : face_vertices(mesh, f))
    {
        out.push_back(v);
    }
    return out;
}

// ADDDIAG: split a quad a b c d by the diagonal a–c into (a, b, c) and (c, d, a).
std::optional<Edit> add_diagonal(const ZomeMesh& mesh, Rng& rng)
{
    const Face f = random_element<Face>(mesh, mesh.faces_size(), rng);
    if (!f.is_valid() || mesh.valence(f) != 4)
    {
        return std::nullopt;
    }
    const std::vector<Vertex> q = corners_of(mesh, f);
    const size_t i = rng() % 2;
    const Vertex a = q[i], b = q[i + 1], c = q[i + 2], d = q[(i + 3) % 4];
    if (!mesh.is_split_ok(f, a, c))
    {
        return std::nullopt;
    }
    Edit e;
    e.kind = "add_diagonal";
    const auto& p = mesh.positions();
    e.change.remove_face(f);
    e.change.add_strut(p[a], p[c]);
    e.change.add_triangle(p[a], p[b], p[c]);
    e.change.add_triangle(p[c], p[d], p[a]);
    e.apply = [f, a, c](ZomeMesh& m) { m.split_face(f, a, c); };
    return e;
}

// The two triangles of an edge u–v and their apexes: face(h) = (u, v, x), face(opposite h) = (v, u, y).
struct Diamond
{
    Edge edge;
    Vertex u, v, x, y;
};

std::optional<Diamond> diamond(const ZomeMesh& mesh, Rng& rng)
{
    const Edge e = random_element<Edge>(mesh, mesh.edges_size(), rng);
    if (!e.is_valid() || !mesh.is_remove_edge_ok(e))
    {
        return std::nullopt;
    }
    const Halfedge h = ZomeMesh::halfedge(e, 0);
    const Halfedge o = ZomeMesh::opposite(h);
    if (mesh.valence(mesh.face(h)) != 3 || mesh.valence(mesh.face(o)) != 3)
    {
        return std::nullopt;
    }
    Diamond d{e, mesh.from_vertex(h), mesh.to_vertex(h), mesh.to_vertex(mesh.next(h)), mesh.to_vertex(mesh.next(o))};
    // Both ends keep at least three struts; the merged quad has four distinct corners.
    if (d.x == d.y || mesh.valence(d.u) < 4 || mesh.valence(d.v) < 4)
    {
        return std::nullopt;
    }
    return d;
}

void remove_diamond(const ZomeMesh& mesh, const Diamond& d, LocalChange& change)
{
    const Halfedge h = ZomeMesh::halfedge(d.edge, 0);
    change.remove_strut(d.edge);
    change.remove_face(mesh.face(h));
    change.remove_face(mesh.face(ZomeMesh::opposite(h)));
}

// REMDIAG: merge the two triangles of u–v into the quad (v, x, u, y).
std::optional<Edit> remove_diagonal(const ZomeMesh& mesh, Rng& rng)
{
    const std::optional<Diamond> d = diamond(mesh, rng);
    if (!d)
    {
        return std::nullopt;
    }
    Edit e;
    e.kind = "remove_diagonal";
    const auto& p = mesh.positions();
    remove_diamond(mesh, *d, e.change);
    e.change.add_quad(p[d->v], p[d->x], p[d->u], p[d->y]);
    e.apply = [edge = d->edge](ZomeMesh& m) { m.remove_edge(edge); };
    return e;
}

// FLIPDIAG: replace u–v by x–y: triangles (x, u, y) and (y, v, x).
std::optional<Edit> flip_diagonal(const ZomeMesh& mesh, Rng& rng)
{
    const std::optional<Diamond> d = diamond(mesh, rng);
    if (!d || mesh.find_edge(d->x, d->y).is_valid())
    {
        return std::nullopt;
    }
    Edit e;
    e.kind = "flip_diagonal";
    const auto& p = mesh.positions();
    remove_diamond(mesh, *d, e.change);
    e.change.add_strut(p[d->x], p[d->y]);
    e.change.add_triangle(p[d->x], p[d->u], p[d->y]);
    e.change.add_triangle(p[d->y], p[d->v], p[d->x]);
    e.apply = [dd = *d](ZomeMesh& m) {
        const Face f = m.remove_edge(dd.edge);
        m.split_face(f, dd.x, dd.y);
    };
    return e;
}

// MOVNODE with unchanged connectivity: move a node by a Zome vector, preferring vectors that keep
// every strut a Zome vector.
std::optional<Edit> move_node(const ZomeMesh& mesh, Rng& rng)
{
    const Vertex v = random_element<Vertex>(mesh, mesh.vertices_size(), rng);
    if (!v.is_valid())
    {
        return std::nullopt;
    }
    const ZVec from = mesh.position(v);
    std::vector<ZVec> zome_keeping, free;
    for (const ZVec& z : zome_vectors())
    {
        const ZVec to = from + z;
        if (!mesh.is_position_free(to))
        {
            continue;
        }
        free.push_back(to);
        bool keeps = true;
        for (Vertex w : adjacent_vertices(mesh, v))
        {
            keeps = keeps && vector_id_of(mesh.position(w) - to) >= 0;
        }
        if (keeps)
        {
            zome_keeping.push_back(to);
        }
    }
    const std::vector<ZVec>& choices = zome_keeping.empty() ? free : zome_keeping;
    if (choices.empty())
    {
        return std::nullopt;
    }
    const ZVec to = choices[rng() % choices.size()];
    Edit e;
    e.kind = "move_node";
    e.change.remove_star(mesh, v);
    e.change.add_node(to);
    for (Vertex w : adjacent_vertices(mesh, v))
    {
        e.change.add_strut(to, mesh.position(w));
    }
    for (Face f : incident_faces(mesh, v))
    {
        std::vector<ZVec> corners;
        for (Vertex c : face_vertices(mesh, f))
        {
            corners.push_back(c == v ? to : mesh.position(c));
        }
        e.change.add_face(corners);
    }
    e.apply = [v, to](ZomeMesh& m) { m.move_vertex(v, to); };
    return e;
}

// INSNODE: a new node at the face centre (when it is a lattice point), possibly offset by a short
// Zome vector, joined to every corner; the face becomes a fan of triangles.
std::optional<Edit> insert_node(const ZomeMesh& mesh, Rng& rng)
{
    const Face f = random_element<Face>(mesh, mesh.faces_size(), rng);
    if (!f.is_valid())
    {
        return std::nullopt;
    }
    const std::vector<Vertex> c = corners_of(mesh, f);
    const int k = static_cast<int>(c.size());
    ZVec sum;
    for (Vertex v : c)
    {
        sum += mesh.position(v);
    }
    ZVec p;
    for (int i = 0; i < 6; ++i)
    {
        if (sum.c[i] % k != 0)
        {
            return std::nullopt;
        }
        p.c[i] = sum.c[i] / k;
    }
    if (rng() % 2 == 0)
    {
        p += zome_vector(static_cast<int>(rng() % kSlotCount) * kSizeCount); // a b0/y0/r0 vector
    }
    if (!mesh.is_position_free(p))
    {
        return std::nullopt;
    }
    Edit e;
    e.kind = "insert_node";
    e.change.remove_face(f);
    e.change.add_node(p);
    for (int i = 0; i < k; ++i)
    {
        e.change.add_strut(mesh.position(c[i]), p);
        e.change.add_triangle(mesh.position(c[i]), mesh.position(c[(i + 1) % k]), p);
    }
    e.apply = [f, c, p](ZomeMesh& m) {
        m.remove_face(f);
        const Vertex n = m.add_vertex(p);
        for (size_t i = 0; i < c.size(); ++i)
        {
            m.add_triangle(c[i], c[(i + 1) % c.size()], n);
        }
    };
    return e;
}

// REMNODE: a node of valence 3 or 4 surrounded by triangles is removed and its link becomes a face.
std::optional<Edit> remove_node(const ZomeMesh& mesh, Rng& rng)
{
    const Vertex v = random_element<Vertex>(mesh, mesh.vertices_size(), rng);
    if (!v.is_valid())
    {
        return std::nullopt;
    }
    std::vector<Vertex> link;
    std::vector<Face> outer;
    for (Halfedge h : outgoing_halfedges(mesh, v))
    {
        if (mesh.valence(mesh.face(h)) != 3 || mesh.valence(mesh.to_vertex(h)) < 4)
        {
            return std::nullopt;
        }
        link.push_back(mesh.to_vertex(h));
        outer.push_back(mesh.face(ZomeMesh::opposite(mesh.next(h))));
    }
    if (link.size() < 3 || link.size() > 4)
    {
        return std::nullopt;
    }
    // The link polygon must not already bound a face on its other side (a tetrahedron).
    if (std::all_of(outer.begin(), outer.end(), [&](Face g) { return g == outer[0]; }))
    {
        return std::nullopt;
    }
    Edit e;
    e.kind = "remove_node";
    e.change.remove_star(mesh, v);
    std::vector<ZVec> corners;
    for (Vertex w : link)
    {
        corners.push_back(mesh.position(w));
    }
    e.change.add_face(corners);
    e.apply = [v, link](ZomeMesh& m) {
        m.remove_vertex(v);
        m.add_face(link);
    };
    return e;
}

using Proposer = std::optional<Edit> (*)(const ZomeMesh&, Rng&);
constexpr Proposer kProposers[] = {add_diagonal, remove_diagonal, flip_diagonal, move_node, insert_node, remove_node};

std::optional<Edit> propose(const ZomeMesh& mesh, Rng& rng)
{
    for (int tries = 0; tries < 100; ++tries)
    {
        if (std::optional<Edit> e = kProposers[rng() % std::size(kProposers)](mesh, rng))
        {
            return e;
        }
    }
    return std::nullopt;
}

ValidateOptions topology_only()
{
    ValidateOptions o;
    o.check_zome = false; // the energy does not care whether the edges are Zome vectors
    return o;
}

EnergyOptions options_for(const ZomeModel& model)
{
    EnergyOptions o;
    o.target_nodes = model.nodes.size() + 3;
    return o;
}

TEST(EnergyIncremental, DeltaEqualsFullRecomputationOnRandomEdits)
{
    constexpr int kEditsPerModel = 150;
    std::map<std::string, int> counts;
    for (const fixtures::NamedModel& named : fixtures::closed_models())
    {
        SCOPED_TRACE(named.name);
        ZomeMesh mesh = from_model(named.model);
        const test::EnergyScene scene = test::sphere_scene_for(named.model, test::energy_test_transform());
        const EnergyOptions options = options_for(named.model);
        EnergyState state(mesh, *scene.context, options);
        Rng rng(12345);
        for (int step = 0; step < kEditsPerModel; ++step)
        {
            std::optional<Edit> edit = propose(mesh, rng);
            ASSERT_TRUE(edit.has_value());
            SCOPED_TRACE(::testing::Message() << "step " << step << " " << edit->kind);
            ASSERT_EQ(check_change(mesh, edit->change), "");
            const EnergyTerms before = evaluate_energy(mesh, *scene.context, options);
            const EnergyDelta delta = state.simulate(mesh, edit->change);
            ASSERT_TRUE(delta.ok());
            const double de = state.delta_energy(delta);

            edit->apply(mesh);
            const ValidationReport report = validate(mesh, topology_only());
            ASSERT_TRUE(report.ok()) << report.message();
            ASSERT_EQ(report.genus, named.genus);
            const EnergyTerms after = evaluate_energy(mesh, *scene.context, options);

            EXPECT_TRUE(before.sums + delta.sums == after.sums);
            const double de_full = energy_change(before.sums, after.sums - before.sums, options);
            EXPECT_NEAR(de, de_full, 1e-9 * std::max(std::abs(de_full), 1e-12));
            EXPECT_NEAR(de, after.total - before.total, 1e-12 * std::max(1.0, std::abs(after.total)));
            ASSERT_TRUE(state.commit(delta));
            ASSERT_TRUE(state.sums() == after.sums);
            EXPECT_DOUBLE_EQ(state.energy(), after.total);
            ++counts[edit->kind];
        }
    }
    for (const auto& [kind, n] : counts)
    {
        EXPECT_GT(n, 20) << kind;
    }
}

TEST(EnergyIncremental, SimulateDoesNotDependOnTheOrderOfTheDescription)
{
    // A node move described with its lists reversed gives the same integers.
    const ZomeModel model = fixtures::cube_shell(3);
    const ZomeMesh mesh = from_model(model);
    const test::EnergyScene scene = test::sphere_scene_for(model, test::energy_test_transform());
    const EnergyOptions options = options_for(model);
    Rng rng(7);
    int compared = 0;
    while (compared < 20)
    {
        std::optional<Edit> e = move_node(mesh, rng);
        if (!e)
        {
            continue;
        }
        LocalChange reversed;
        const LocalChange& c = e->change;
        for (size_t i = c.removed_faces().size(); i-- > 0;)
        {
            reversed.remove_face(c.removed_faces()[i]);
        }
        for (size_t i = c.removed_struts().size(); i-- > 0;)
        {
            reversed.remove_strut(c.removed_struts()[i]);
        }
        reversed.remove_node(c.removed_nodes()[0]);
        reversed.add_node(c.added_nodes()[0]);
        for (size_t i = c.added_struts().size(); i-- > 0;)
        {
            reversed.add_strut(c.added_struts()[i].b, c.added_struts()[i].a);
        }
        for (size_t i = c.added_faces().size(); i-- > 0;)
        {
            // Same face, starting at another corner.
            const NewFace& f = c.added_faces()[i];
            std::vector<ZVec> rotated(f.view().begin() + 1, f.view().end());
            rotated.push_back(f.corners[0]);
            reversed.add_face(rotated);
        }
        const EnergyDelta a = simulate_change(mesh, c, *scene.context, options);
        const EnergyDelta b = simulate_change(mesh, reversed, *scene.context, options);
        ASSERT_TRUE(a.ok());
        EXPECT_TRUE(a.sums == b.sums);
        ++compared;
    }
}

TEST(EnergyIncremental, ConcurrentSimulationsAgreeWithSerialOnes)
{
    const ZomeModel model = fixtures::cube_shell(3);
    const ZomeMesh mesh = from_model(model);
    const test::EnergyScene scene = test::sphere_scene_for(model, test::energy_test_transform());
    const EnergyOptions options = options_for(model);
    Rng rng(99);
    std::vector<Edit> edits;
    while (edits.size() < 200)
    {
        if (std::optional<Edit> e = propose(mesh, rng))
        {
            edits.push_back(std::move(*e));
        }
    }
    std::vector<EnergySums> serial;
    for (const Edit& e : edits)
    {
        serial.push_back(simulate_change(mesh, e.change, *scene.context, options).sums);
    }
    scene.context->clear_cache(); // the threads fill the cache concurrently
    std::vector<std::vector<EnergySums>> results(3);
    std::vector<std::thread> threads;
    for (size_t t = 0; t < results.size(); ++t)
    {
        threads.emplace_back([&, t] {
            for (const Edit& e : edits)
            {
                results[t].push_back(simulate_change(mesh, e.change, *scene.context, options).sums);
            }
        });
    }
    for (std::thread& th : threads)
    {
        th.join();
    }
    for (const auto& r : results)
    {
        ASSERT_EQ(r.size(), serial.size());
        for (size_t i = 0; i < r.size(); ++i)
        {
            EXPECT_TRUE(r[i] == serial[i]) << "edit " << i;
        }
    }
}

TEST(EnergyIncremental, InconsistentDescriptionsAreReported)
{
    const ZomeModel model = fixtures::cube_shell(1);
    const ZomeMesh mesh = from_model(model);
    const test::EnergyScene scene = test::sphere_scene_for(model, test::energy_test_transform());
    const EnergyOptions options = options_for(model);

    // A strut to a node that is neither new nor on the removed region.
    LocalChange c;
    c.add_strut(mesh.position(Vertex(0)), mesh.position(Vertex(7)));
    EXPECT_EQ(simulate_change(mesh, c, *scene.context, options).status, ChangeStatus::UnknownNode);
    EXPECT_NE(check_change(mesh, c), "");

    // A removed node whose struts are kept.
    c.clear();
    c.remove_node(Vertex(0));
    EXPECT_EQ(simulate_change(mesh, c, *scene.context, options).status, ChangeStatus::KeptStrutToRemovedNode);
    EXPECT_NE(check_change(mesh, c), "");

    // Faces must be triangles or quads; a full list refuses and is reported.
    c.clear();
    const std::vector<ZVec> pentagon(5);
    EXPECT_FALSE(c.add_face(pentagon));
    EXPECT_EQ(simulate_change(mesh, c, *scene.context, options).status, ChangeStatus::Overflow);
    c.clear();
    for (size_t i = 0; i < LocalChange::kMaxNodes; ++i)
    {
        EXPECT_TRUE(c.add_node(ZVec{}));
    }
    EXPECT_FALSE(c.add_node(ZVec{}));
    EXPECT_TRUE(c.overflowed());
    EnergyState state(mesh, *scene.context, options);
    const EnergySums before = state.sums();
    const EnergyDelta bad = state.simulate(mesh, c);
    EXPECT_FALSE(bad.ok());
    EXPECT_EQ(state.delta_energy(bad), 0.0);
    EXPECT_FALSE(state.commit(bad));
    EXPECT_TRUE(state.sums() == before);
}

} // namespace
} // namespace zomeify
