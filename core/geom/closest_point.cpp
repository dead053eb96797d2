#include "core/geom/closest_point.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "core/base/errors.h"
#include "core/base/portable_math.h"
#include "core/geom/triangle_estimate.h"

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
                throw InvalidInputError("surface triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) +
                                        ", out of range");
            }
        }
    }
    return mesh;
}

// Angle between two edge vectors; atan2 stays accurate for angles near 0 and pi, where acos of a
// dot product would not. The portable one: libm's atan2 differs in the last bit between glibc and
// musl, and these angles weight the vertex normals the energy reads.
double corner_angle(const Vec3& e1, const Vec3& e2) { return portable_angle(e1.cross(e2).norm(), e1.dot(e2)); }

// Queries are done in float relative to the BVH origin while the magnitude (largest coordinate
// of the query plus the mesh's half extent) stays within this range: squares of distances then
// neither overflow nor lose precision to subnormals.
constexpr double kFloatRangeMax = 1e15;
constexpr double kFloatRangeMin = 1e-15;

// Float box distances are within a few float epsilons of the magnitude of the truth (beyond the
// padding of the boxes); a margin of 1e-6 * magnitude covers that.
constexpr double kBoxMargin = 1e-6;

// The order of triangles as answers: by exact distance, then by index. Triangles that tie (a
// closest point on a shared edge or vertex) are common; breaking ties by index makes the answer
// a function of p alone, whatever the traversal order or the hint.
inline bool closer_than(double distance, uint32_t id, double best, uint32_t best_id)
{
    return distance < best || (distance == best && id < best_id);
}

// Candidates held before they are measured exactly (then the buffer starts over).
constexpr int kCandidates = 32;

// r² rounded up to float and never above FLT_MAX, so that the empty children of a node (box
// distance +inf) are never kept.
float squared_rounded_up(double r)
{
    // Rounding to nearest float is off by at most 2^-24 relative; scaling up by more first makes
    // the result an upper bound without a libm call.
    const double x = r * r * (1.0 + 1.2e-7);
    if (!(x < static_cast<double>(std::numeric_limits<float>::max())))
    {
        return std::numeric_limits<float>::max();
    }
    return static_cast<float>(x);
}

// Sort key of a kept child: float bits of a non-negative distance order like the distances.
uint64_t child_key(float distance_squared, uint32_t child)
{
    uint32_t bits = 0;
    std::memcpy(&bits, &distance_squared, sizeof(bits));
    return (static_cast<uint64_t>(bits) << 32) | child;
}

float key_distance_squared(uint64_t key)
{
    const auto bits = static_cast<uint32_t>(key >> 32);
    float distance_squared = 0.0f;
    std::memcpy(&distance_squared, &bits, sizeof(bits));
    return distance_squared;
}

void compare_exchange(uint64_t& a, uint64_t& b)
{
    const uint64_t lo = std::min(a, b);
    b = std::max(a, b);
    a = lo;
}

simd::F4 load4(const std::array<float, 4>& values)
{
    simd::F4 v;
    std::memcpy(&v, values.data(), sizeof(v));
    return v;
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
    // Outside the float range every query takes search_all(), which needs the slots only.
    const bool float_range = half_extent_ >= kFloatRangeMin && half_extent_ <= kFloatRangeMax;
    blocks_.reserve(float_range ? wide_.leaves().size() : 0);
    slots_.reserve(4 * wide_.leaves().size());
    const double sliver_width = TriangleBlockTolerance::kSliverWidth * half_extent_;
    for (const WideBvhLeaf& leaf : wide_.leaves())
    {
        const uint32_t* ids = bvh_.order().data() + leaf.first;
        if (float_range)
        {
            blocks_.push_back(make_triangle_block(mesh_, ids, leaf.count, bvh_.origin(), sliver_width));
        }
        for (uint32_t lane = 0; lane < 4; ++lane)
        {
            const uint32_t id = ids[lane < leaf.count ? lane : 0];
            const auto& tri = mesh_.triangles[id];
            slots_.push_back({mesh_.positions[tri[0]], mesh_.positions[tri[1]], mesh_.positions[tri[2]], id});
        }
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
    // Measured by the same kernel as the search's candidates, so that the hint and the search
    // agree bit for bit on its distance and ties are broken alike (closer_than).
    const auto& tri = mesh_.triangles[hint];
    double best =
        point_triangle_distance_squared(p, mesh_.positions[tri[0]], mesh_.positions[tri[1]], mesh_.positions[tri[2]]);
    uint32_t best_id = hint;
    search(p, best, best_id);
    return finish(p, best_id);
}

void SurfaceProjector::search(const Vec3& p, double& best, uint32_t& best_id) const
{
    const Vec3& origin = bvh_.origin();
    const double magnitude =
        std::max({std::abs(p.x() - origin.x()), std::abs(p.y() - origin.y()), std::abs(p.z() - origin.z())}) +
        half_extent_;
    if (!(magnitude <= kFloatRangeMax && half_extent_ >= kFloatRangeMin))
    {
        search_all(p, best, best_id);
        return;
    }

    // Inner nodes put aside, nearest last. Each level leaves at most three siblings behind.
    struct Entry
    {
        uint32_t node;
        float distance_squared;
    };
    Entry stack[3 * Bvh::kMaxDepth + 4];
    int top = 0;
    // A triangle that may be the closest: leaf * 4 + lane, and its estimated squared distance.
    struct Candidate
    {
        uint32_t slot;
        float estimate;
    };
    Candidate candidates[kCandidates];
    int held = 0;

    const WideBvhNode* nodes = wide_.nodes().data();
    const TriangleBlock* blocks = blocks_.data();
    const simd::F4 px = simd::splat(static_cast<float>(p.x() - origin.x()));
    const simd::F4 py = simd::splat(static_cast<float>(p.y() - origin.y()));
    const simd::F4 pz = simd::splat(static_cast<float>(p.z() - origin.z()));
    const simd::F4 zero = simd::splat(0.0f);
    const double inside_margin = TriangleBlockTolerance::kInsideMargin * magnitude;
    const simd::F4 inside_margin2 = simd::splat(static_cast<float>(inside_margin * inside_margin));
    const double box_margin = kBoxMargin * magnitude;
    const double slack = TriangleBlockTolerance::kSlack * magnitude;

    // `upper` bounds the distance from p to S from above: by the best exact distance, and by every
    // estimate plus its slack. A box farther than that (plus the box margin) holds nothing closer;
    // a triangle whose estimate exceeds it by more than the slack is not the closest.
    double upper = std::sqrt(best);
    float lowest_estimate = std::numeric_limits<float>::infinity();
    float node_window = squared_rounded_up(upper + box_margin);
    float candidate_window = squared_rounded_up(upper + slack);
    auto lower_upper = [&](double bound) {
        if (bound < upper)
        {
            upper = bound;
            node_window = squared_rounded_up(upper + box_margin);
            candidate_window = squared_rounded_up(upper + slack);
        }
    };
    // Measures the held candidates that are still in the window exactly, in double.
    auto measure = [&] {
        for (int i = 0; i < held; ++i)
        {
            if (candidates[i].estimate > candidate_window)
            {
                continue;
            }
            const SlotTriangle& t = slots_[candidates[i].slot];
            const double dist = point_triangle_distance_squared(p, t.a, t.b, t.c);
            if (closer_than(dist, t.id, best, best_id))
            {
                best = dist;
                best_id = t.id;
            }
        }
        held = 0;
        lower_upper(std::sqrt(best));
    };
    // A node is two cache lines, a block three.
    auto prefetch_child = [&](uint32_t child) {
        const char* address = WideBvhNode::is_leaf(child)
                                  ? reinterpret_cast<const char*>(blocks + WideBvhNode::leaf_index(child))
                                  : reinterpret_cast<const char*>(nodes + child);
        prefetch(address);
        prefetch(address + 64);
        if (WideBvhNode::is_leaf(child))
        {
            prefetch(address + 128);
        }
    };
    // Estimates a leaf's triangles; keeps those in the window as candidates (without branches).
    auto visit_leaf = [&](uint32_t child) {
        const uint32_t leaf = WideBvhNode::leaf_index(child);
        const uint32_t lanes = WideBvhNode::leaf_count(child);
        const simd::F4 estimate = estimate_distances_squared(blocks[leaf], px, py, pz, inside_margin2);
        for (uint32_t lane = 0; lane < 4; ++lane)
        {
            candidates[held] = {leaf * 4 + lane, estimate[lane]};
            held += lane < lanes && estimate[lane] <= candidate_window ? 1 : 0;
        }
        // Unused lanes repeat lane 0, so the minimum over all four is the leaf's.
        const float lowest = std::min(std::min(estimate[0], estimate[1]), std::min(estimate[2], estimate[3]));
        if (lowest < lowest_estimate)
        {
            lowest_estimate = lowest;
            lower_upper(std::sqrt(static_cast<double>(lowest)) + slack);
            // The new best will most likely be measured: fetch its corners now.
            for (uint32_t lane = 0; lane < lanes; ++lane)
            {
                if (estimate[lane] == lowest)
                {
                    const char* slot = reinterpret_cast<const char*>(&slots_[4 * leaf + lane]);
                    prefetch(slot);
                    prefetch(slot + sizeof(SlotTriangle) - 1);
                }
            }
        }
        if (held > kCandidates - 4)
        {
            measure();
        }
    };

    uint32_t node_index = 0;
    for (;;)
    {
        const WideBvhNode& node = nodes[node_index];
        const simd::F4 dx = simd::max(simd::max(load4(node.min_x) - px, px - load4(node.max_x)), zero);
        const simd::F4 dy = simd::max(simd::max(load4(node.min_y) - py, py - load4(node.max_y)), zero);
        const simd::F4 dz = simd::max(simd::max(load4(node.min_z) - pz, pz - load4(node.max_z)), zero);
        const simd::F4 d = dx * dx + dy * dy + dz * dz;
        const simd::I4 keep = d <= simd::splat(node_window);
        // Children in the window, nearest first, by a sorting network on (distance, child) keys;
        // empty children have infinite box distances and are never kept. Their data is
        // requested first, so that the misses of several children overlap.
        uint64_t key[4];
        int count = 0;
        for (int j = 0; j < 4; ++j)
        {
            if (keep[j] != 0)
            {
                prefetch_child(node.child[j]);
            }
            key[j] = keep[j] != 0 ? child_key(d[j], node.child[j]) : ~uint64_t{0};
            count += keep[j] != 0 ? 1 : 0;
        }
        compare_exchange(key[0], key[1]);
        compare_exchange(key[2], key[3]);
        compare_exchange(key[0], key[2]);
        compare_exchange(key[1], key[3]);
        compare_exchange(key[1], key[2]);
        // Leaves are estimated on the spot, nearest first (cheap, and they tighten the window);
        // then the nearest inner child still in the window is walked next and the others are put
        // aside, farther first, and prefetched.
        for (int k = 0; k < count; ++k)
        {
            const auto child = static_cast<uint32_t>(key[k]);
            if (WideBvhNode::is_leaf(child) && key_distance_squared(key[k]) <= node_window)
            {
                visit_leaf(child);
            }
        }
        uint32_t next = WideBvhNode::kEmpty;
        float next_distance_squared = 0.0f;
        for (int k = count - 1; k >= 0; --k)
        {
            const auto child = static_cast<uint32_t>(key[k]);
            const float distance_squared = key_distance_squared(key[k]);
            if (WideBvhNode::is_leaf(child) || distance_squared > node_window)
            {
                continue;
            }
            if (next != WideBvhNode::kEmpty)
            {
                stack[top++] = {next, next_distance_squared};
            }
            next = child;
            next_distance_squared = distance_squared;
        }
        if (next != WideBvhNode::kEmpty)
        {
            node_index = next;
            continue;
        }
        // Pop the nearest node put aside that may still hold something closer.
        while (top > 0 && stack[top - 1].distance_squared > node_window)
        {
            --top;
        }
        if (top == 0)
        {
            measure();
            return;
        }
        node_index = stack[--top].node;
    }
}

void SurfaceProjector::search_all(const Vec3& p, double& best, uint32_t& best_id) const
{
    const std::vector<WideBvhLeaf>& leaves = wide_.leaves();
    for (size_t leaf = 0; leaf < leaves.size(); ++leaf)
    {
        for (uint32_t lane = 0; lane < leaves[leaf].count; ++lane)
        {
            const SlotTriangle& t = slots_[4 * leaf + lane];
            const double dist = point_triangle_distance_squared(p, t.a, t.b, t.c);
            if (closer_than(dist, t.id, best, best_id))
            {
                best = dist;
                best_id = t.id;
            }
        }
    }
}

size_t SurfaceProjector::memory_bytes() const
{
    return sizeof(*this) + mesh_.positions.capacity() * sizeof(Vec3) +
           mesh_.triangles.capacity() * sizeof(mesh_.triangles[0]) +
           (vertex_normals_.capacity() + face_normals_.capacity()) * sizeof(Vec3) +
           slots_.capacity() * sizeof(SlotTriangle) + bvh_.nodes().capacity() * sizeof(BvhNode) +
           wide_.nodes().capacity() * sizeof(WideBvhNode) + wide_.leaves().capacity() * sizeof(WideBvhLeaf) +
           blocks_.capacity() * sizeof(TriangleBlock) + bvh_.order().capacity() * sizeof(uint32_t);
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
