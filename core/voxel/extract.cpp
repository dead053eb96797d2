#include "core/voxel/extract.h"

#include <numeric>
#include <unordered_map>

#include "core/zome/qphi.h"

namespace zomeify {

namespace {

// Union-find over node indices, for counting the boundary's components.
class Components
{
public:
    explicit Components(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
    uint32_t find(uint32_t x)
    {
        while (parent_[x] != x)
            x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void join(uint32_t a, uint32_t b) { parent_[find(a)] = find(b); }
    int count()
    {
        int n = 0;
        for (uint32_t i = 0; i < parent_.size(); ++i)
            n += find(i) == i;
        return n;
    }

private:
    std::vector<uint32_t> parent_;
};

} // namespace

ZVec grid_corner_node(int i, int j, int k) { return ZVec{{2 * i, 0, 2 * j, 0, 2 * k, 0}}; }

Extraction extract_boundary(const VoxelGrid& grid)
{
    const auto& d = grid.dims();
    const size_t vx = d[0] + 1, vy = d[1] + 1, vz = d[2] + 1;
    // Node ids by grid corner. A dense table is the fastest lookup and costs 4 bytes per corner,
    // which is small next to the cell array for any grid this tool builds.
    std::vector<uint32_t> node_of(vx * vy * vz, UINT32_MAX);
    Extraction out;
    ZomeModel& m = out.model;

    auto node = [&](int i, int j, int k) {
        uint32_t& id = node_of[(static_cast<size_t>(k) * vy + j) * vx + i];
        if (id == UINT32_MAX)
        {
            id = static_cast<uint32_t>(m.nodes.size());
            m.nodes.push_back(grid_corner_node(i, j, k));
        }
        return id;
    };

    // Struts are keyed by the lower corner and the axis: each boundary edge appears in two quads.
    std::unordered_map<uint64_t, uint32_t> strut_of;
    auto strut = [&](const std::array<int, 3>& p, const std::array<int, 3>& q, uint32_t a, uint32_t b) {
        const auto& lo = p < q ? p : q;
        const int axis = p[0] != q[0] ? 0 : p[1] != q[1] ? 1 : 2;
        const uint64_t key = ((static_cast<uint64_t>(lo[2]) * vy + lo[1]) * vx + lo[0]) * 3 + axis;
        if (strut_of.emplace(key, static_cast<uint32_t>(m.struts.size())).second)
            m.struts.push_back({a, b});
    };

    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i)
            {
                if (!grid.occupied(i, j, k))
                    continue;
                const std::array<int, 3> c{i, j, k};
                for (int a = 0; a < 3; ++a)
                    for (int s = 0; s < 2; ++s)
                    {
                        auto nb = c;
                        nb[a] += s ? 1 : -1;
                        if (grid.occupied(nb[0], nb[1], nb[2]))
                            continue;
                        // The face at c[a] + s. With u, w the next axes cyclically (u × w = axis a),
                        // corners (0,0), (1,0), (1,1), (0,1) in (u, w) run counter-clockwise seen from
                        // +a; the −a face takes them in the opposite order.
                        const int u = (a + 1) % 3, w = (a + 2) % 3;
                        std::array<std::array<int, 3>, 4> corners;
                        const int order[2][4][2] = {{{0, 0}, {0, 1}, {1, 1}, {1, 0}}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
                        for (int q = 0; q < 4; ++q)
                        {
                            corners[q] = c;
                            corners[q][a] += s;
                            corners[q][u] += order[s][q][0];
                            corners[q][w] += order[s][q][1];
                        }
                        std::vector<uint32_t> face(4);
                        for (int q = 0; q < 4; ++q)
                            face[q] = node(corners[q][0], corners[q][1], corners[q][2]);
                        for (int q = 0; q < 4; ++q)
                            strut(corners[q], corners[(q + 1) % 4], face[q], face[(q + 1) % 4]);
                        m.faces.push_back(std::move(face));
                    }
            }

    m.transform.scale = grid.spec().cell / kPhi;
    m.transform.translation = {grid.spec().origin.x(), grid.spec().origin.y(), grid.spec().origin.z()};

    Components comps(m.nodes.size());
    for (const auto& s : m.struts)
        comps.join(s[0], s[1]);
    out.topology.components = comps.count();
    out.topology.euler = static_cast<long long>(m.nodes.size()) - static_cast<long long>(m.struts.size()) +
                         static_cast<long long>(m.faces.size());
    out.topology.genus = out.topology.components - out.topology.euler / 2;
    return out;
}

} // namespace zomeify
