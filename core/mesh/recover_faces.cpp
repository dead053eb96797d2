#include "core/mesh/recover_faces.h"
#include "core/mesh/dir3.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace zomeify {
namespace {

using namespace dir3;

//! Neighbours of every node sorted counter-clockwise around its normal.
bool sorted_rotations(const ZomeModel& model, const std::vector<Dir>& normals,
                      std::vector<std::vector<uint32_t>>& rotation, std::string& error)
{
    const size_t n = model.nodes.size();
    rotation.assign(n, {});
    for (const auto& s : model.struts)
    {
        rotation[s[0]].push_back(s[1]);
        rotation[s[1]].push_back(s[0]);
    }
    std::vector<Dir> pos(n);
    for (size_t i = 0; i < n; ++i)
        pos[i] = model.nodes[i].to_double();
    for (size_t v = 0; v < n; ++v)
    {
        if (rotation[v].size() < 3)
        {
            error = "node " + std::to_string(v) + " has " + std::to_string(rotation[v].size()) +
                    " struts; a closed surface needs at least 3";
            return false;
        }
        const Dir normal = unit(normals[v]);
        // A tangent frame: any direction not parallel to the normal, made orthogonal.
        const Dir seed = std::abs(normal[0]) < 0.9 ? Dir{1, 0, 0} : Dir{0, 1, 0};
        const Dir t1 = unit(cross(seed, normal));
        const Dir t2 = cross(normal, t1);
        std::vector<std::pair<double, uint32_t>> angled;
        for (uint32_t u : rotation[v])
        {
            const Dir d = sub(pos[u], pos[v]);
            angled.emplace_back(std::atan2(dot(d, t2), dot(d, t1)), u);
        }
        std::sort(angled.begin(), angled.end());
        for (size_t k = 0; k < angled.size(); ++k)
            rotation[v][k] = angled[k].second;
    }
    return true;
}

} // namespace

FaceRecovery recover_faces(const ZomeModel& model, const std::vector<Dir>& normals)
{
    FaceRecovery out;
    const size_t n = model.nodes.size();
    if (normals.size() != n)
    {
        out.error = "one normal per node is needed";
        return out;
    }
    for (const auto& s : model.struts)
        if (s[0] >= n || s[1] >= n || s[0] == s[1])
        {
            out.error = "a strut refers to a missing node or joins a node to itself";
            return out;
        }
    std::vector<std::vector<uint32_t>> rotation;
    if (!sorted_rotations(model, normals, rotation, out.error))
        return out;

    out.faces = trace_faces(rotation);
    size_t bad = 0, largest = 0;
    for (const auto& face : out.faces)
    {
        std::vector<uint32_t> sorted = face;
        std::sort(sorted.begin(), sorted.end());
        const bool repeats = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
        if (face.size() < 3 || face.size() > 4 || repeats)
        {
            ++bad;
            largest = std::max(largest, face.size());
        }
    }
    if (bad > 0)
    {
        out.error = std::to_string(bad) + " of " + std::to_string(out.faces.size()) +
                    " traced faces are not simple triangles or quads (largest has " + std::to_string(largest) +
                    " corners): the normals do not order the struts as a surface";
        out.faces.clear();
        return out;
    }
    out.ok = true;
    return out;
}

std::vector<std::vector<uint32_t>> trace_faces(const std::vector<std::vector<uint32_t>>& rotation)
{
    const size_t n = rotation.size();
    // Darts u→v are numbered by (u, position of v in u's rotation).
    std::vector<size_t> first(n + 1, 0);
    for (size_t v = 0; v < n; ++v)
        first[v + 1] = first[v] + rotation[v].size();
    auto index_in = [&](uint32_t at, uint32_t of) -> size_t {
        const auto& r = rotation[at];
        return static_cast<size_t>(std::find(r.begin(), r.end(), of) - r.begin());
    };
    std::vector<char> used(first[n], 0);
    std::vector<std::vector<uint32_t>> faces;
    for (uint32_t u = 0; u < n; ++u)
        for (size_t k = 0; k < rotation[u].size(); ++k)
        {
            if (used[first[u] + k])
                continue;
            std::vector<uint32_t> face;
            uint32_t a = u;
            size_t ak = k;
            // The next dart after a→b is b→c with c just before a counter-clockwise around b:
            // the face lies between b→c and b→a.
            while (ak < rotation[a].size() && !used[first[a] + ak])
            {
                used[first[a] + ak] = 1;
                face.push_back(a);
                const uint32_t b = rotation[a][ak];
                const auto& rb = rotation[b];
                const size_t at = index_in(b, a);
                if (at == rb.size())
                    break; // a strut listed at one end only
                ak = (at + rb.size() - 1) % rb.size();
                a = b;
            }
            faces.push_back(std::move(face));
        }
    return faces;
}

std::vector<Dir> centroid_normals(const ZomeModel& model)
{
    Dir c{0, 0, 0};
    for (const ZVec& p : model.nodes)
    {
        const Dir d = p.to_double();
        for (int k = 0; k < 3; ++k)
            c[k] += d[k];
    }
    const double count = static_cast<double>(std::max<size_t>(model.nodes.size(), 1));
    for (double& x : c)
        x /= count;
    std::vector<Dir> normals;
    normals.reserve(model.nodes.size());
    for (const ZVec& p : model.nodes)
        normals.push_back(sub(p.to_double(), c));
    return normals;
}

} // namespace zomeify
