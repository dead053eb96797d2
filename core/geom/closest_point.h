#pragma once
//! \file closest_point.h
//! π(p): the closest point on the input surface S and the surface normal there (design §3.3,
//! §3.7). The hot query of the annealer's distance and orientation energies.

#include <array>
#include <cstdint>
#include <vector>

#include "core/geom/bvh.h"
#include "core/geom/point_triangle.h"
#include "core/geom/triangle_block.h"
#include "core/geom/triangle_mesh.h"
#include "core/geom/wide_bvh.h"

namespace zomeify {

//! The answer of one π(p) query.
struct ClosestPoint
{
    Vec3 point = Vec3::Zero();                       //!< π(p)
    Vec3 normal = Vec3::UnitZ();                     //!< unit outward normal at π(p), see SurfaceProjector
    Vec3 barycentric = Vec3::Zero();                 //!< weights of the triangle's corners at π(p)
    double distance_squared = 0.0;                   //!< ‖p − π(p)‖²
    uint32_t triangle = 0;                           //!< index into mesh().triangles
    TriangleFeature feature = TriangleFeature::face; //!< where on the triangle π(p) lies
};

//! Closest-point queries on a triangle mesh through a BVH. Construction copies the mesh, computes
//! angle-weighted vertex normals and builds the BVH; afterwards the object is immutable and
//! `project` may be called from any number of threads at once (no shared mutable state, no heap
//! allocation per query).
//!
//! A query walks a 4-wide BVH (WideBvh) nearest box first, four box distances at a time in float
//! SIMD. Each leaf is a TriangleBlock: the distances to its (up to) four triangles are estimated
//! together in float, with a proven error bound (TriangleBlockTolerance). Only triangles whose
//! estimate is within that bound of the best estimate are kept; at the end (usually one or a few
//! triangles sharing the closest feature) they are measured exactly in double, and the closest
//! wins. So the answer is the exact double result of the closest triangle, as a brute-force scan
//! would give, while the search itself does no double arithmetic. Children are prefetched when
//! pushed: random queries are bound by memory latency as much as by arithmetic.
//! p must be finite. Queries very far from the mesh (beyond 1e15 times its size, where float
//! squares overflow) or on a mesh smaller than 1e-15 fall back to an exact scan of all triangles.
//!
//! The normal is the angle-weighted vertex normals (Thürmer & Wüthrich) of the closest triangle,
//! interpolated with the barycentrics of π(p) and normalised (design §3.3). Where that sum
//! vanishes (opposite corner normals on a paper-thin part) the face normal is used instead.
class SurfaceProjector
{
public:
    //! Throws InvalidInputError if the mesh has no triangles, an index out of range or a
    //! non-finite coordinate. The mesh should be closed and oriented outward (faces CCW).
    explicit SurfaceProjector(TriangleMesh mesh, const BvhOptions& options = {});

    //! π(p) by nearest-first BVH traversal. Exact up to rounding: equal to the minimum over all
    //! triangles; among triangles at exactly the same distance (π(p) on a shared edge or vertex),
    //! the lowest index. So the answer depends on p only.
    ClosestPoint project(const Vec3& p) const;

    //! The same answer, bit for bit, but starts from triangle `hint` (e.g. the answer for a nearby
    //! point), which bounds the search from the first node on. An out-of-range hint is ignored.
    ClosestPoint project(const Vec3& p, uint32_t hint) const;

    const TriangleMesh& mesh() const { return mesh_; }
    const Bvh& bvh() const { return bvh_; }
    const WideBvh& wide_bvh() const { return wide_; }
    //! Unit angle-weighted normal per vertex (zero for a vertex of degenerate triangles only).
    const std::vector<Vec3>& vertex_normals() const { return vertex_normals_; }
    //! Unit normal per triangle (zero for a zero-area triangle).
    const std::vector<Vec3>& face_normals() const { return face_normals_; }
    //! Bytes held (mesh copy, normals, BVH and the search's own arrays).
    size_t memory_bytes() const;

private:
    //! Lowers (best_distance_squared, best_id) to the closest triangle; best_id stays if none is closer.
    void search(const Vec3& p, double& best_distance_squared, uint32_t& best_id) const;
    //! The same by measuring every triangle: the fallback for queries outside float range.
    void search_all(const Vec3& p, double& best_distance_squared, uint32_t& best_id) const;
    //! The full answer on triangle `id`.
    ClosestPoint finish(const Vec3& p, uint32_t id) const;

    TriangleMesh mesh_;
    std::vector<Vec3> vertex_normals_;
    std::vector<Vec3> face_normals_;
    Bvh bvh_;
    WideBvh wide_;
    //! Half the largest extent of the mesh: with the query's offset from the BVH origin, the
    //! magnitude that float rounding of box distances is relative to.
    double half_extent_ = 0.0;
    //! A triangle's corners in double and its index in mesh().triangles: what the exact
    //! measurement of a candidate reads, in one place.
    struct SlotTriangle
    {
        Vec3 a, b, c;
        uint32_t id;
    };
    //! One block per leaf of wide_, in the same order.
    std::vector<TriangleBlock> blocks_;
    //! Four per leaf (slot = leaf * 4 + lane), like the blocks' lanes; unused lanes repeat lane 0.
    std::vector<SlotTriangle> slots_;
};

} // namespace zomeify
