#include "core/geom/closest_point.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/base/errors.h"

namespace zomeify {
namespace {

TriangleMesh validated(TriangleMesh mesh)
{
    if (mesh.triangles.empty())
    {
        throw InvalidInputError("surface has no triangles");
    }
    for (const Vec3& p : mesh.positions)
    {
        if (!p.allFinite())
        {
            throw InvalidInputError("surface has a non-finite vertex coordinate");
        }
    }
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
    {
        for (const uint32_t v : mesh.triangles[t])
        {
            if (v >= mesh.positions.size())
            {
                throw InvalidInputError("surface triangle " + std::to_string(t) + " uses vertex " +
                                        std::to_string(v) + ", out of range");
            }
        }
    }
    return mesh;
}

// Angle between two edge vectors; atan2 stays accurate for angles near 0 and pi, where acos of a
// dot product would not.
double corner_angle(const Vec3& e1, const Vec3& e2)
{
    return std::atan2(e1.cross(e2).norm(), e1.dot(e2));
}

// Float box distances are within a few float epsilons of `magnitude` of the truth (beyond the
// padding of the boxes); a margin of 1e-6 * magnitude covers that. Boxes are kept while their
// squared distance is at most (best + margin)^2, rounded up, and never above FLT_MAX, so that
// the empty child of a one-leaf root (box distance +inf) is never pushed.
float window(double best_distance_squared, double margin)
{
    const double r = std::sqrt(best_distance_squared) + margin;
    const double x = r * r;
    if (!(x < static_cast<double>(std::numeric_limits<float>::max())))
    {
        return std::numeric_limits<float>::max();
    }
    const float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// Starts loading what a stack entry points to while the traversal works on something else: a
// random query misses the caches on most nodes and triangles, so overlapping those misses is
// worth more than any arithmetic saving. A hint only; compiles to nothing where unsupported.
inline void prefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(address);
#else
    (void)address;
#endif
}

} // namespace

SurfaceProjector::SurfaceProjector(TriangleMesh mesh, const BvhOptions& options)
    : mesh_(validated(std::move(mesh))), bvh_(triangle_boxes(mesh_), options), wide_(bvh_)
{
    vertex_normals_.assign(mesh_.positions.size(), Vec3::Zero());
    face_normals_.reserve(mesh_.triangles.size());
    for (const auto& tri : mesh_.triangles)
    {
        const Vec3& p0 = mesh_.positions[tri[0]];
        const Vec3& p1 = mesh_.positions[tri[1]];
        const Vec3& p2 = mesh_.positions[tri[2]];
        const Vec3 n = (p1 - p0).cross(p2 - p0);
        const double len = n.norm();
        const Vec3 unit = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
        face_normals_.push_back(unit);
        vertex_normals_[tri[0]] += corner_angle(p1 - p0, p2 - p0) * unit;
        vertex_normals_[tri[1]] += corner_angle(p2 - p1, p0 - p1) * unit;
        vertex_normals_[tri[2]] += corner_angle(p0 - p2, p1 - p2) * unit;
    }
    for (Vec3& n : vertex_normals_)
    {
        const double len = n.norm();
        n = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
    }
    half_extent_ = 0.5 * bvh_.bounds().extent().maxCoeff();
    std::vector<uint32_t> renumber(mesh_.positions.size(), BvhNode::kInvalid);
    leaf_triangles_.reserve(mesh_.triangles.size());
    for (const uint32_t t : bvh_.order())
    {
        std::array<uint32_t, 3> local{};
        for (int k = 0; k < 3; ++k)
        {
            const uint32_t v = mesh_.triangles[t][k];
            if (renumber[v] == BvhNode::kInvalid)
            {
                renumber[v] = static_cast<uint32_t>(leaf_vertices_.size());
                leaf_vertices_.push_back(mesh_.positions[v]);
            }
            local[k] = renumber[v];
        }
        leaf_triangles_.push_back(local);
    }
}

ClosestPoint SurfaceProjector::project(const Vec3& p) const
{
    double best = std::numeric_limits<double>::infinity();
    uint32_t best_id = 0;
    search(p, best, best_id);
    return finish(p, best_id);
}

ClosestPoint SurfaceProjector::project(const Vec3& p, uint32_t hint) const
{
    if (hint >= mesh_.triangles.size())
    {
        return project(p);
    }
    const auto& tri = mesh_.triangles[hint];
    double best =
        closest_point_on_triangle(p, mesh_.positions[tri[0]], mesh_.positions[tri[1]], mesh_.positions[tri[2]])
            .distance_squared;
    uint32_t best_id = hint;
    search(p, best, best_id);
    return finish(p, best_id);
}

void SurfaceProjector::search(const Vec3& p, double& best, uint32_t& best_id) const
{
    struct Entry
    {
        uint32_t child;
        float distance_squared;
    };
    // Each level leaves at most three siblings behind, plus the four children of the last node.
    Entry stack[3 * Bvh::kMaxDepth + 4];
    int top = 0;

    const WideBvhNode* nodes = wide_.nodes().data();
    const std::array<uint32_t, 3>* triangles = leaf_triangles_.data();
    const Vec3* vertices = leaf_vertices_.data();
    const uint32_t* ids = bvh_.order().data();
    const Vec3& origin = bvh_.origin();
    const float px = static_cast<float>(p.x() - origin.x());
    const float py = static_cast<float>(p.y() - origin.y());
    const float pz = static_cast<float>(p.z() - origin.z());
    // Box distances are lower bounds up to float rounding (boxes rounded outward and padded);
    // they are compared against the best distance widened by a margin for that rounding.
    const double magnitude =
        std::max({std::abs(p.x() - origin.x()), std::abs(p.y() - origin.y()), std::abs(p.z() - origin.z())}) +
        half_extent_;
    const double margin = 1e-6 * magnitude;
    float bound = window(best, margin);

    uint32_t node_index = 0;
    for (;;)
    {
        const WideBvhNode& node = nodes[node_index];
        // Four box distances in straight-line code the compiler can keep in vector registers.
        float d[4];
        for (int j = 0; j < 4; ++j)
        {
            const float dx = std::max(std::max(node.min_x[j] - px, px - node.max_x[j]), 0.0f);
            const float dy = std::max(std::max(node.min_y[j] - py, py - node.max_y[j]), 0.0f);
            const float dz = std::max(std::max(node.min_z[j] - pz, pz - node.max_z[j]), 0.0f);
            d[j] = dx * dx + dy * dy + dz * dz;
        }
        // Survivors go on the stack farthest first, so the nearest is popped next.
        Entry near[4];
        int count = 0;
        for (int j = 0; j < 4; ++j)
        {
            if (node.child[j] != WideBvhNode::kEmpty && d[j] <= bound)
            {
                Entry e{node.child[j], d[j]};
                int k = count++;
                for (; k > 0 && near[k - 1].distance_squared < e.distance_squared; --k)
                {
                    near[k] = near[k - 1];
                }
                near[k] = e;
            }
        }
        for (int k = 0; k < count; ++k)
        {
            const uint32_t c = near[k].child;
            if (WideBvhNode::is_leaf(c))
            {
                prefetch(triangles + WideBvhNode::leaf_first(c));
            }
            else
            {
                // A node is two cache lines.
                prefetch(nodes + c);
                prefetch(reinterpret_cast<const char*>(nodes + c) + 64);
            }
            stack[top++] = near[k];
        }
        // Pop the nearest pending entry that may still hold something closer; leaves are tested
        // on the spot, an inner node ends the loop and is expanded above.
        bool descend = false;
        while (top > 0)
        {
            const Entry e = stack[--top];
            if (e.distance_squared > bound)
            {
                continue;
            }
            if (!WideBvhNode::is_leaf(e.child))
            {
                node_index = e.child;
                descend = true;
                break;
            }
            const uint32_t first = WideBvhNode::leaf_first(e.child);
            const uint32_t end = first + WideBvhNode::leaf_count(e.child);
            for (uint32_t k = first; k < end; ++k)
            {
                const std::array<uint32_t, 3>& t = triangles[k];
                const double dist = point_triangle_distance_squared(p, vertices[t[0]], vertices[t[1]], vertices[t[2]]);
                if (dist < best)
                {
                    best = dist;
                    best_id = ids[k];
                    bound = window(best, margin);
                }
            }
        }
        if (!descend)
        {
            return;
        }
    }
}

size_t SurfaceProjector::memory_bytes() const
{
    return sizeof(*this) + mesh_.positions.capacity() * sizeof(Vec3) +
           mesh_.triangles.capacity() * sizeof(mesh_.triangles[0]) +
           (vertex_normals_.capacity() + face_normals_.capacity() + leaf_vertices_.capacity()) * sizeof(Vec3) +
           leaf_triangles_.capacity() * sizeof(leaf_triangles_[0]) + bvh_.nodes().capacity() * sizeof(BvhNode) +
           wide_.nodes().capacity() * sizeof(WideBvhNode) +
           bvh_.order().capacity() * sizeof(uint32_t);
}

ClosestPoint SurfaceProjector::finish(const Vec3& p, uint32_t id) const
{
    // The search compared distances only; the point, barycentrics and feature come from the
    // robust kernel on the winning triangle, in the mesh's own coordinates.
    const auto& tri = mesh_.triangles[id];
    const TrianglePoint best =
        closest_point_on_triangle(p, mesh_.positions[tri[0]], mesh_.positions[tri[1]], mesh_.positions[tri[2]]);
    ClosestPoint out;
    out.point = best.point;
    out.barycentric = best.barycentric;
    out.distance_squared = best.distance_squared;
    out.triangle = id;
    out.feature = best.feature;
    const Vec3 n = best.barycentric[0] * vertex_normals_[tri[0]] + best.barycentric[1] * vertex_normals_[tri[1]] +
                   best.barycentric[2] * vertex_normals_[tri[2]];
    const double len = n.norm();
    if (len > 1e-12)
    {
        out.normal = n / len;
    }
    else if (face_normals_[id].squaredNorm() > 0.0)
    {
        out.normal = face_normals_[id];
    }
    else
    {
        // A zero-area triangle whose corners cancel: the largest-weight corner's normal is the
        // best local guess; the default +z remains only for an isolated degenerate triangle.
        int k = 0;
        best.barycentric.maxCoeff(&k);
        if (vertex_normals_[tri[k]].squaredNorm() > 0.0)
        {
            out.normal = vertex_normals_[tri[k]];
        }
    }
    return out;
}

} // namespace zomeify
