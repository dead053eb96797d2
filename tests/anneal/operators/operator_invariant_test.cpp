// The invariant test of issue 5: random valid operator applications, all accepted, on several
// fixtures including genus 1 and 2. After every application (debug builds) or every 1000
// (release), validate(): closed 2-manifold, genus unchanged, tri/quad faces, Zome struts, unique
// positions, no slot conflicts, valence ≥ 3. The number of applications is ZOME_INVARIANT_OPS
// (default 10^6 natively; 10^5 under a sanitizer or in wasm, where everything is many times
// slower), shared equally among the fixtures; ZOME_VALIDATE_EVERY overrides the validation
// period (ZOME_VALIDATE_EVERY=1 checks after every commit in a release build too). Prints
// proposals, acceptances and rejection reasons per kind.
#include <array>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "tests/anneal/operators/operator_test_support.h"
#include "tests/support/zome_fixtures.h"

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define ZOME_SLOW_BUILD 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__) || defined(__EMSCRIPTEN__)
#define ZOME_SLOW_BUILD 1
#endif

namespace zomeify {
namespace {

#ifdef ZOME_SLOW_BUILD
constexpr long kDefaultOps = 100000;
#else
constexpr long kDefaultOps = 1000000;
#endif
#ifdef NDEBUG
constexpr long kValidateEvery = 1000;
#else
constexpr long kValidateEvery = 1;
#endif

struct KindStats
{
    long proposed = 0, applied = 0;
    std::array<long, kRejectionKinds> rejected{};
};

// Keeps the model between half and twice its initial size: above 1.5× the node-adding kinds are
// replaced by REMNODE, below 0.75× REMNODE is replaced by INSNODE.
OperatorKind pick_kind(Rng& rng, size_t nodes, size_t initial)
{
    auto kind = static_cast<OperatorKind>(rng.below(kOperatorKinds));
    if (2 * nodes > 3 * initial && (kind == OperatorKind::InsNode || kind == OperatorKind::SplitStrut))
        return OperatorKind::RemNode;
    if (4 * nodes < 3 * initial && kind == OperatorKind::RemNode)
        return OperatorKind::InsNode;
    return kind;
}

// Quads whose diagonal is also a strut (two faces folded onto each other; never buildable).
size_t folded_quads(const ZomeMesh& mesh)
{
    size_t folded = 0;
    for (Face f : faces(mesh))
    {
        if (mesh.valence(f) != 4)
            continue;
        const Halfedge h = mesh.halfedge(f);
        const Vertex a = mesh.from_vertex(h), b = mesh.to_vertex(h);
        const Vertex c = mesh.to_vertex(mesh.next(h)), d = mesh.to_vertex(mesh.next(mesh.next(h)));
        if (mesh.find_edge(a, c).is_valid() || mesh.find_edge(b, d).is_valid())
            ++folded;
    }
    return folded;
}

TEST(OperatorInvariants, RandomApplicationsKeepEveryInvariant)
{
    std::vector<fixtures::NamedModel> models;
    models.push_back({"cube_shell(3)", fixtures::cube_shell(3), 0, true});
    models.push_back({"torus_shell", fixtures::torus_shell(), 1, true});
    models.push_back({"double_torus_shell", fixtures::double_torus_shell(), 2, true});
    models.push_back({"rhombic double torus",
                      fixtures::voxel_surface(fixtures::double_torus_cells(), fixtures::rhombohedral_basis()), 2,
                      true});
    models.push_back({"icosahedron", fixtures::icosahedron(), 0, true});
    const long total = test::env_count("ZOME_INVARIANT_OPS", kDefaultOps);
    const long per_model = std::max(1L, total / static_cast<long>(models.size()));
    const long validate_every = std::max(1L, test::env_count("ZOME_VALIDATE_EVERY", kValidateEvery));
    std::array<KindStats, kOperatorKinds> stats{};
    Proposal p;
    for (const fixtures::NamedModel& named : models)
    {
        SCOPED_TRACE(named.name);
        ZomeMesh mesh = from_model(named.model);
        ASSERT_TRUE(validate(mesh).ok()) << validate(mesh).message();
        const size_t initial = mesh.n_vertices();
        Rng rng(std::hash<std::string>()(named.name) & 0xFFFF);
        long applied = 0, attempts = 0;
        while (applied < per_model)
        {
            ASSERT_LT(++attempts, 200 * per_model + 100000) << "too few valid proposals";
            const OperatorKind kind = pick_kind(rng, mesh.n_vertices(), initial);
            KindStats& s = stats[static_cast<size_t>(kind)];
            ++s.proposed;
            if (!test::propose_at(kind, mesh, test::random_node(mesh, rng), rng, p))
            {
                ++s.rejected[static_cast<size_t>(p.rejection)];
                continue;
            }
            apply_proposal(mesh, p);
            ++s.applied;
            ++applied;
            if (applied % validate_every == 0 || applied == per_model)
            {
                const ValidationReport report = validate(mesh);
                ASSERT_TRUE(report.ok()) << "after " << applied << " applications, last " << operator_name(kind) << ": "
                                         << report.message();
                ASSERT_EQ(report.genus, named.genus) << "after " << applied << " applications";
                ASSERT_EQ(folded_quads(mesh), 0u)
                    << "after " << applied << " applications, last " << operator_name(kind);
            }
            if (mesh.n_vertices() * 4 < mesh.vertices_size())
                mesh.garbage_collection();
        }
        std::printf("[ model    ] %-22s %zu → %zu nodes, %zu faces\n", named.name.c_str(), initial, mesh.n_vertices(),
                    mesh.n_faces());
    }
    std::printf("[ kinds    ] %-10s %10s %10s  rejections\n", "kind", "proposed", "applied");
    for (int k = 0; k < kOperatorKinds; ++k)
    {
        const KindStats& s = stats[static_cast<size_t>(k)];
        std::string reasons;
        for (int r = 1; r < kRejectionKinds; ++r)
            if (s.rejected[static_cast<size_t>(r)] > 0)
                reasons += std::string(rejection_name(static_cast<Rejection>(r))) + " " +
                           std::to_string(s.rejected[static_cast<size_t>(r)]) + ", ";
        std::printf("[ kinds    ] %-10s %10ld %10ld  %s\n",
                    std::string(operator_name(static_cast<OperatorKind>(k))).c_str(), s.proposed, s.applied,
                    reasons.c_str());
        EXPECT_GT(s.applied, 0) << operator_name(static_cast<OperatorKind>(k));
    }
}

} // namespace
} // namespace zomeify
