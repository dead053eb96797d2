#include "tests/support/zome_fixtures.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/zome/slots.h"

namespace zomeify::fixtures {

namespace {

ZVec scaled(const ZVec& v, int k)
{
    ZVec out;
    for (int i = 0; i < 6; ++i)
        out.c[i] = v.c[i] * k;
    return out;
}

double det3(const LatticeBasis& b)
{
    const auto u = b.u.to_double(), v = b.v.to_double(), w = b.w.to_double();
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// One strut per distinct face edge, in order of first appearance.
void add_struts_from_faces(ZomeModel& model)
{
    std::set<std::pair<uint32_t, uint32_t>> seen;
    for (const auto& f : model.faces)
        for (size_t i = 0; i < f.size(); ++i)
        {
            const uint32_t a = f[i], b = f[(i + 1) % f.size()];
            if (seen.insert({std::min(a, b), std::max(a, b)}).second)
                model.struts.push_back({a, b});
        }
}

using Vec3 = std::array<double, 3>;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The faces of a convex polyhedron whose face normals are known: the nodes farthest along each
// normal, sorted by angle around it (counter-clockwise seen from outside).
ZomeModel convex_polyhedron(const std::vector<ZVec>& nodes, const std::vector<ZVec>& normals)
{
    ZomeModel model;
    model.nodes = nodes;
    for (const ZVec& nz : normals)
    {
        const Vec3 n = nz.to_double();
        double best = -1e300;
        for (const ZVec& p : nodes)
            best = std::max(best, dot(p.to_double(), n));
        std::vector<uint32_t> face;
        Vec3 centre{0, 0, 0};
        for (uint32_t i = 0; i < nodes.size(); ++i)
            if (dot(nodes[i].to_double(), n) > best - 1e-9)
            {
                face.push_back(i);
                for (int k = 0; k < 3; ++k)
                    centre[k] += nodes[i].coord(k);
            }
        for (double& c : centre)
            c /= static_cast<double>(face.size());
        const auto rel = [&](uint32_t i) {
            const Vec3 p = nodes[i].to_double();
            return Vec3{p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
        };
        const Vec3 e1 = rel(face[0]);
        const Vec3 e2 = cross(n, e1);
        std::sort(face.begin(), face.end(), [&](uint32_t a, uint32_t b) {
            return std::atan2(dot(rel(a), e2), dot(rel(a), e1)) < std::atan2(dot(rel(b), e2), dot(rel(b), e1));
        });
        model.faces.push_back(std::move(face));
    }
    add_struts_from_faces(model);
    return model;
}

} // namespace

LatticeBasis b1_basis() { return {ZVec{{2, 0, 0, 0, 0, 0}}, ZVec{{0, 0, 2, 0, 0, 0}}, ZVec{{0, 0, 0, 0, 2, 0}}}; }

LatticeBasis rhombohedral_basis()
{
    // Found by search: these three R0 struts (slots 50, 52, 54) have u ± v, v ± w and u ± w all
    // Zome vectors, so both diagonals of every face of the rhombohedron are struts.
    return {zome_vector(vector_id(50, 0)), zome_vector(vector_id(52, 0)), zome_vector(vector_id(54, 0))};
}

ZomeModel voxel_surface(const std::vector<Cell>& cells, const LatticeBasis& basis)
{
    const std::set<Cell> occupied(cells.begin(), cells.end());
    const bool flip = det3(basis) < 0;
    ZomeModel model;
    std::map<Cell, uint32_t> node_of;
    const auto node = [&](const Cell& p) {
        const auto [it, inserted] = node_of.emplace(p, static_cast<uint32_t>(model.nodes.size()));
        if (inserted)
            model.nodes.push_back(scaled(basis.u, p[0]) + scaled(basis.v, p[1]) + scaled(basis.w, p[2]));
        return it->second;
    };
    for (const Cell& c : occupied)
        for (int a = 0; a < 3; ++a)
            for (int side = 0; side < 2; ++side)
            {
                Cell nb = c;
                nb[a] += side ? 1 : -1;
                if (occupied.count(nb))
                    continue;
                // Corners p, p+e_b, p+e_b+e_c, p+e_c with (a, b, c) cyclic turn counter-clockwise
                // around +e_a; the −e_a face and a left-handed basis reverse the order.
                const int b = (a + 1) % 3, cc = (a + 2) % 3;
                Cell p = c;
                p[a] += side;
                Cell pb = p, pbc = p, pc = p;
                pb[b] += 1;
                pbc[b] += 1;
                pbc[cc] += 1;
                pc[cc] += 1;
                std::vector<uint32_t> quad{node(p), node(pb), node(pbc), node(pc)};
                if ((side == 0) != flip)
                    std::reverse(quad.begin(), quad.end());
                model.faces.push_back(std::move(quad));
            }
    add_struts_from_faces(model);
    return model;
}

std::vector<Cell> block_cells(int nx, int ny, int nz)
{
    std::vector<Cell> cells;
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < nz; ++k)
                cells.push_back({i, j, k});
    return cells;
}

std::vector<Cell> torus_cells()
{
    std::vector<Cell> cells = block_cells(3, 3, 1);
    std::erase(cells, Cell{1, 1, 0});
    return cells;
}

std::vector<Cell> double_torus_cells()
{
    std::vector<Cell> cells = block_cells(5, 3, 1);
    std::erase(cells, Cell{1, 1, 0});
    std::erase(cells, Cell{3, 1, 0});
    return cells;
}

ZomeModel cube_shell(int n) { return voxel_surface(block_cells(n, n, n)); }

ZomeModel torus_shell() { return voxel_surface(torus_cells()); }

ZomeModel double_torus_shell() { return voxel_surface(double_torus_cells()); }

ZomeModel icosahedron()
{
    std::vector<ZVec> nodes, normals;
    for (int s = kBlueSlots + kYellowSlots; s < kSlotCount; ++s)
        nodes.push_back(zome_vector(vector_id(s, 0)));
    for (int s = kBlueSlots; s < kBlueSlots + kYellowSlots; ++s)
        normals.push_back(zome_vector(vector_id(s, 0)));
    return convex_polyhedron(nodes, normals);
}

ZomeModel dodecahedron()
{
    std::vector<ZVec> nodes, normals;
    for (int s = kBlueSlots; s < kBlueSlots + kYellowSlots; ++s)
        nodes.push_back(zome_vector(vector_id(s, 1)));
    for (int s = kBlueSlots + kYellowSlots; s < kSlotCount; ++s)
        normals.push_back(zome_vector(vector_id(s, 0)));
    return convex_polyhedron(nodes, normals);
}

std::vector<NamedModel> closed_models()
{
    return {
        {"cube_shell_1", cube_shell(1), 0, true},
        {"cube_shell_3", cube_shell(3), 0, true},
        {"torus_shell", torus_shell(), 1, true},
        {"double_torus_shell", double_torus_shell(), 2, true},
        {"rhombo_block_2", voxel_surface(block_cells(2, 2, 2), rhombohedral_basis()), 0, true},
        {"rhombo_torus", voxel_surface(torus_cells(), rhombohedral_basis()), 1, true},
        {"rhombo_double_torus", voxel_surface(double_torus_cells(), rhombohedral_basis()), 2, true},
        {"icosahedron", icosahedron(), 0, true},
    };
}

} // namespace zomeify::fixtures
