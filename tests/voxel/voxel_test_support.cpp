#include "tests/voxel/voxel_test_support.h"

#include <algorithm>
#include <map>
#include <mutex>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "core/zome/slots.h"
#include "tests/support/generated_shapes.h"
#include "tests/support/paths.h"

namespace zomeify::voxel_test {

const std::vector<std::string>& shared_mesh_names()
{
    static const std::vector<std::string> names = {"fertility", "rockerarm", "bunny", "elk",    "torus",
                                                   "sphere",    "cube",      "eight", "3holes", "scorpion"};
    return names;
}

const LoadedSurface& shared_surface(const std::string& name)
{
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<LoadedSurface>> cache;
    std::lock_guard lock(mutex);
    auto& slot = cache[name];
    if (!slot)
    {
        auto s = std::make_unique<LoadedSurface>();
        PreparedSurface prepared = prepare_surface(read_mesh_file(test::shared_path("data/meshes/" + name + ".obj")));
        s->mesh = std::move(prepared.mesh);
        s->genus = prepared.report.genus;
        s->projector = std::make_unique<SurfaceProjector>(s->mesh);
        s->inside = std::make_unique<InsideTest>(*s->projector);
        slot = std::move(s);
    }
    return *slot;
}

const LoadedSurface& generated_surface(const std::string& name)
{
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<LoadedSurface>> cache;
    std::lock_guard lock(mutex);
    auto& slot = cache[name];
    if (!slot)
    {
        for (const test::GeneratedShape& g : test::generated_shapes())
            if (g.name == name)
            {
                auto s = std::make_unique<LoadedSurface>();
                s->mesh = g.mesh;
                s->genus = g.genus;
                s->projector = std::make_unique<SurfaceProjector>(s->mesh);
                s->inside = std::make_unique<InsideTest>(*s->projector);
                slot = std::move(s);
            }
        if (!slot)
            throw std::out_of_range("no generated shape '" + name + "'");
    }
    return *slot;
}

std::string closed_manifold_problem(const ZomeModel& model)
{
    std::ostringstream err;
    const uint32_t n = static_cast<uint32_t>(model.nodes.size());
    // Directed face edges: each must occur once, and its reverse once.
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const auto& f : model.faces)
        for (size_t q = 0; q < f.size(); ++q)
        {
            const uint32_t a = f[q], b = f[(q + 1) % f.size()];
            if (a >= n || b >= n)
                return "face index out of range";
            if (++directed[{a, b}] > 1)
                return "a directed edge occurs in two faces (non-manifold or inconsistent orientation)";
        }
    std::set<std::pair<uint32_t, uint32_t>> struts;
    for (const auto& s : model.struts)
        struts.insert({std::min(s[0], s[1]), std::max(s[0], s[1])});
    if (struts.size() != model.struts.size())
        return "a strut occurs twice";
    for (const auto& [e, count] : directed)
    {
        if (!directed.count({e.second, e.first}))
        {
            err << "edge " << e.first << "-" << e.second << " has a face on one side only (not closed)";
            return err.str();
        }
        if (!struts.count({std::min(e.first, e.second), std::max(e.first, e.second)}))
            return "a face edge is not a strut";
    }
    if (directed.size() != 2 * struts.size())
        return "a strut lies in no face";
    // One fan per node. For a face u -> v -> w, the face on the other side of v -> u follows it
    // around v; mapping the out-edge v -> w to v -> u is thus a permutation of v's out-edges, and
    // the faces at v form one disc exactly when that permutation is a single cycle.
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> next_around; // (v, w) -> u: face has u -> v -> w
    for (const auto& f : model.faces)
        for (size_t q = 0; q < f.size(); ++q)
        {
            const uint32_t u = f[(q + f.size() - 1) % f.size()], v = f[q], w = f[(q + 1) % f.size()];
            next_around[{v, w}] = u;
        }
    std::vector<size_t> out_degree(n, 0);
    for (const auto& [e, u] : next_around)
        ++out_degree[e.first];
    std::vector<uint8_t> seen_node(n, 0);
    for (const auto& [e, u0] : next_around)
    {
        const uint32_t v = e.first;
        if (seen_node[v])
            continue;
        seen_node[v] = 1;
        size_t steps = 0;
        uint32_t w = e.second;
        do
        {
            w = next_around.at({v, w});
            ++steps;
        } while (w != e.second && steps <= out_degree[v]);
        if (steps != out_degree[v])
        {
            err << "node " << v << " has more than one fan of faces (non-manifold vertex)";
            return err.str();
        }
    }
    for (uint32_t v = 0; v < n; ++v)
        if (!out_degree[v])
            return "a node lies in no face";
    return {};
}

std::string lattice_problem(const ZomeModel& model)
{
    std::unordered_set<ZVec, ZVecHash> positions(model.nodes.begin(), model.nodes.end());
    if (positions.size() != model.nodes.size())
        return "two nodes share a position";
    for (const auto& s : model.struts)
    {
        const ZVec d = model.nodes[s[1]] - model.nodes[s[0]];
        const int id = vector_id_of(d);
        if (id < 0 || vector_kind(id) != StrutKind::B1)
            return "a strut is not a B1";
        int nonzero = 0;
        for (int a = 0; a < 3; ++a)
            nonzero += d.c[2 * a] != 0 || d.c[2 * a + 1] != 0;
        if (nonzero != 1)
            return "a B1 strut is not along a coordinate axis";
    }
    return {};
}

std::string halfedge_problem(const ZomeModel& model, long long* genus)
{
    try
    {
        const ValidationReport report = validate(from_model(model));
        if (genus)
            *genus = report.genus;
        return report.ok() ? std::string() : report.message();
    }
    catch (const std::exception& e)
    {
        return e.what();
    }
}

long long model_genus(const ZomeModel& model)
{
    std::vector<uint32_t> parent(model.nodes.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](uint32_t x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    };
    for (const auto& s : model.struts)
        parent[find(s[0])] = find(s[1]);
    long long components = 0;
    for (uint32_t i = 0; i < parent.size(); ++i)
        components += find(i) == i;
    const long long euler = static_cast<long long>(model.nodes.size()) - static_cast<long long>(model.struts.size()) +
                            static_cast<long long>(model.faces.size());
    return components - euler / 2;
}

} // namespace zomeify::voxel_test
