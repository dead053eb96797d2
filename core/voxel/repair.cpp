#include "core/voxel/repair.h"

#include <array>
#include <deque>
#include <vector>

#include "core/voxel/simple_voxel.h"

namespace zomeify {

namespace {

// The 8 cells around a vertex are the corners of a unit cube (bit i = axis i); two cells share a
// face when their bits differ in one place, and the four cells around one of the vertex's 6 grid
// edges are the cube's faces with one bit fixed.
bool star_connected(uint8_t set)
{
    if (!set)
        return true;
    uint8_t comp = static_cast<uint8_t>(set & (~set + 1));
    for (;;)
    {
        uint8_t next = comp;
        for (int b = 0; b < 8; ++b)
            if (comp & (1u << b))
                for (int a = 0; a < 3; ++a)
                    next |= static_cast<uint8_t>(1u << (b ^ (1 << a)));
        next &= set;
        if (next == comp)
            return comp == set;
        comp = next;
    }
}

bool has_diagonal_edge(uint8_t star)
{
    for (int fixed = 0; fixed < 3; ++fixed)
    {
        const int u = 1 << ((fixed + 1) % 3), w = 1 << ((fixed + 2) % 3);
        for (int side = 0; side < 2; ++side)
        {
            const int base = side << fixed;
            const bool c00 = star >> base & 1, c11 = star >> (base | u | w) & 1;
            const bool c10 = star >> (base | u) & 1, c01 = star >> (base | w) & 1;
            if (c00 == c11 && c10 == c01 && c00 != c10)
                return true;
        }
    }
    return false;
}

std::array<bool, 256> make_manifold_table()
{
    std::array<bool, 256> t{};
    for (int s = 0; s < 256; ++s)
    {
        const uint8_t star = static_cast<uint8_t>(s);
        t[s] = !has_diagonal_edge(star) && star_connected(star) && star_connected(static_cast<uint8_t>(~star));
    }
    return t;
}

class Repairer
{
public:
    Repairer(VoxelGrid& grid, const RepairOptions& options)
        : grid_(grid), options_(options), flipped_(grid.cell_count(), 0)
    {
        const auto& d = grid.dims();
        vdims_ = {d[0] + 1, d[1] + 1, d[2] + 1};
    }

    RepairReport run()
    {
        RepairReport report;
        for (int z = 0; z < vdims_[2]; ++z)
            for (int y = 0; y < vdims_[1]; ++y)
                for (int x = 0; x < vdims_[0]; ++x)
                    if (bad(x, y, z))
                    {
                        queue_.push_back({x, y, z});
                        ++report.initial_bad_vertices;
                    }
        while (!queue_.empty())
        {
            const auto v = queue_.front();
            queue_.pop_front();
            if (bad(v[0], v[1], v[2]))
                fix(v, report);
        }
        report.remaining_bad_vertices = count_nonmanifold_vertices(grid_);
        report.manifold = report.remaining_bad_vertices == 0;
        return report;
    }

private:
    bool bad(int x, int y, int z) const { return !is_manifold_star(vertex_star(grid_, x, y, z)); }

    // Non-manifold vertices among the 8 corners of cell c.
    int bad_corners(const std::array<int, 3>& c) const
    {
        int n = 0;
        for (int b = 0; b < 8; ++b)
            n += bad(c[0] + (b & 1), c[1] + (b >> 1 & 1), c[2] + (b >> 2 & 1));
        return n;
    }

    int face_neighbours(const std::array<int, 3>& c) const
    {
        int n = 0;
        for (int a = 0; a < 3; ++a)
            for (int s = -1; s <= 1; s += 2)
            {
                auto q = c;
                q[a] += s;
                n += grid_.occupied(q[0], q[1], q[2]);
            }
        return n;
    }

    void flip(const std::array<int, 3>& c, Cell to) { grid_.set(c[0], c[1], c[2], to); }

    // Chooses, among the simple cells of the vertex's star that were not flipped yet, the flip that
    // best cleans up: first one that makes this vertex manifold, then the one that removes the most
    // non-manifold corners, then (geometry) removing a cell S only crosses, adding a cell, and last
    // removing a cell inside S; ties go to the cell with the fewest (removal) or most (addition)
    // occupied face neighbours, i.e. the one that sticks out or fills a notch.
    void fix(const std::array<int, 3>& v, RepairReport& report)
    {
        struct Candidate
        {
            std::array<int, 3> cell;
            Cell to;
            std::array<int, 4> key; // larger is better
        };
        bool found = false;
        Candidate best{};
        for (int b = 0; b < 8; ++b)
        {
            const std::array<int, 3> c{v[0] - 1 + (b & 1), v[1] - 1 + (b >> 1 & 1), v[2] - 1 + (b >> 2 & 1)};
            if (!grid_.contains(c[0], c[1], c[2]) || flipped_[grid_.index(c[0], c[1], c[2])])
                continue;
            const Cell before = grid_.at(c[0], c[1], c[2]);
            const bool removal = before != Cell::Empty;
            if (!removal && (!options_.allow_additions || on_border(c)))
                continue;
            if (!is_simple(neighbourhood(grid_, c[0], c[1], c[2])))
                continue;
            const int bad_before = bad_corners(c);
            const Cell after = removal ? Cell::Empty : Cell::Added;
            flip(c, after);
            const int resolves = bad(v[0], v[1], v[2]) ? 0 : 1;
            const int gain = bad_before - bad_corners(c);
            flip(c, before);
            const int kind = removal ? (before == Cell::Inside ? 0 : 2) : 1;
            const int shape = removal ? -face_neighbours(c) : face_neighbours(c);
            const Candidate cand{c, after, {resolves, gain, kind, shape}};
            if (!found || cand.key > best.key)
            {
                best = cand;
                found = true;
            }
        }
        if (!found)
            return; // nothing simple left here: the caller's final count reports it
        flip(best.cell, best.to);
        flipped_[grid_.index(best.cell[0], best.cell[1], best.cell[2])] = 1;
        if (best.to == Cell::Empty)
            ++report.removed;
        else
            ++report.added;
        for (int b = 0; b < 8; ++b)
        {
            const std::array<int, 3> w{best.cell[0] + (b & 1), best.cell[1] + (b >> 1 & 1),
                                       best.cell[2] + (b >> 2 & 1)};
            if (bad(w[0], w[1], w[2]))
                queue_.push_back(w);
        }
    }

    bool on_border(const std::array<int, 3>& c) const
    {
        for (int a = 0; a < 3; ++a)
            if (c[a] == 0 || c[a] == grid_.dims()[a] - 1)
                return true;
        return false;
    }

    VoxelGrid& grid_;
    const RepairOptions& options_;
    std::vector<uint8_t> flipped_;
    std::array<int, 3> vdims_{};
    std::deque<std::array<int, 3>> queue_;
};

} // namespace

VertexStar vertex_star(const VoxelGrid& grid, int vx, int vy, int vz)
{
    VertexStar s = 0;
    for (int b = 0; b < 8; ++b)
        if (grid.occupied(vx - 1 + (b & 1), vy - 1 + (b >> 1 & 1), vz - 1 + (b >> 2 & 1)))
            s |= static_cast<VertexStar>(1u << b);
    return s;
}

bool is_manifold_star(VertexStar star)
{
    static const std::array<bool, 256> table = make_manifold_table();
    return table[star];
}

bool corners_manifold(const VoxelGrid& grid, int i, int j, int k)
{
    for (int c = 0; c < 8; ++c)
        if (!is_manifold_star(vertex_star(grid, i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))))
            return false;
    return true;
}

size_t count_nonmanifold_vertices(const VoxelGrid& grid)
{
    const auto& d = grid.dims();
    size_t n = 0;
    for (int z = 0; z <= d[2]; ++z)
        for (int y = 0; y <= d[1]; ++y)
            for (int x = 0; x <= d[0]; ++x)
                n += !is_manifold_star(vertex_star(grid, x, y, z));
    return n;
}

RepairReport repair_manifold(VoxelGrid& grid, const RepairOptions& options) { return Repairer(grid, options).run(); }

} // namespace zomeify
