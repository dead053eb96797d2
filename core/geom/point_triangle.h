#pragma once
//! \file point_triangle.h
//! Closest point on one triangle: the inner kernel of π(p). Inline because the BVH traversal calls
//! it for every candidate triangle.

#include <cstdint>

#include <Eigen/Geometry>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! The part of a triangle (corners 0, 1, 2) that holds its closest point to a query.
enum class TriangleFeature : uint8_t
{
    face,
    edge01,
    edge12,
    edge20,
    vertex0,
    vertex1,
    vertex2,
};

//! Closest point of one triangle to a query point.
struct TrianglePoint
{
    Vec3 point;              //!< the closest point
    Vec3 barycentric;        //!< weights of corners 0, 1, 2 (sum 1; exactly 0 off the feature)
    double distance_squared; //!< squared distance from the query to `point`
    TriangleFeature feature; //!< face interior, an edge or a corner
};

namespace detail {

//! Closest point on segment [a, a + ab] as the parameter t in [0, 1]; t = 0 for a zero-length segment.
inline double segment_parameter(const Vec3& ap, const Vec3& ab)
{
    const double len2 = ab.squaredNorm();
    if (!(len2 > 0.0))
    {
        return 0.0;
    }
    const double t = ap.dot(ab) / len2;
    return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
}

//! The closest of the three edges: always a point of the triangle, so it is the safe answer when
//! the face-region arithmetic cannot be trusted (zero-area and sliver triangles).
inline TrianglePoint closest_on_edges(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const double t0 = segment_parameter(p - a, b - a);
    const double t1 = segment_parameter(p - b, c - b);
    const double t2 = segment_parameter(p - c, a - c);
    const Vec3 q0 = a + t0 * (b - a);
    const Vec3 q1 = b + t1 * (c - b);
    const Vec3 q2 = c + t2 * (a - c);
    const double d0 = (p - q0).squaredNorm();
    const double d1 = (p - q1).squaredNorm();
    const double d2 = (p - q2).squaredNorm();
    // Parameters at 0 or 1 mean a corner; name the feature by what the point really is.
    auto edge_feature = [](double t, TriangleFeature edge, TriangleFeature start, TriangleFeature end) {
        return t <= 0.0 ? start : (t >= 1.0 ? end : edge);
    };
    if (d0 <= d1 && d0 <= d2)
    {
        return {q0, Vec3(1.0 - t0, t0, 0.0), d0,
                edge_feature(t0, TriangleFeature::edge01, TriangleFeature::vertex0, TriangleFeature::vertex1)};
    }
    if (d1 <= d2)
    {
        return {q1, Vec3(0.0, 1.0 - t1, t1), d1,
                edge_feature(t1, TriangleFeature::edge12, TriangleFeature::vertex1, TriangleFeature::vertex2)};
    }
    return {q2, Vec3(t2, 0.0, 1.0 - t2), d2,
            edge_feature(t2, TriangleFeature::edge20, TriangleFeature::vertex2, TriangleFeature::vertex0)};
}

//! True if two corners coincide. The region walk then divides by a zero edge length, or (corners
//! a and b equal) takes the corner region for the whole edge ac; the edges alone are the answer.
inline bool has_zero_edge(const Vec3& ab, const Vec3& ac)
{
    return ab == Vec3::Zero() || ac == Vec3::Zero() || ab == ac;
}

} // namespace detail

//! Closest point of triangle (a, b, c) to `p`, by Voronoi regions of the corners, edges and face
//! (the classic region walk, Ericson, Real-Time Collision Detection §5.1.5). Robust for degenerate
//! input: two equal corners go straight to the closest edge point; every division is guarded, and
//! when the face region is reached with a (near) zero-area triangle or inconsistent signs from
//! cancellation, the answer falls back to the closest edge point.
inline TrianglePoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    if (detail::has_zero_edge(ab, ac))
    {
        return detail::closest_on_edges(p, a, b, c);
    }
    const Vec3 ap = p - a;
    const double d1 = ab.dot(ap);
    const double d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0)
    {
        return {a, Vec3(1.0, 0.0, 0.0), ap.squaredNorm(), TriangleFeature::vertex0};
    }
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp);
    const double d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3)
    {
        return {b, Vec3(0.0, 1.0, 0.0), bp.squaredNorm(), TriangleFeature::vertex1};
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
    {
        // d1 - d3 = |ab|^2 > 0 here unless ab is degenerate; the guard keeps t finite.
        const double den = d1 - d3;
        const double t = den > 0.0 ? d1 / den : 0.0;
        const Vec3 q = a + t * ab;
        return {q, Vec3(1.0 - t, t, 0.0), (p - q).squaredNorm(), TriangleFeature::edge01};
    }
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp);
    const double d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6)
    {
        return {c, Vec3(0.0, 0.0, 1.0), cp.squaredNorm(), TriangleFeature::vertex2};
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
    {
        const double den = d2 - d6;
        const double t = den > 0.0 ? d2 / den : 0.0;
        const Vec3 q = a + t * ac;
        return {q, Vec3(1.0 - t, 0.0, t), (p - q).squaredNorm(), TriangleFeature::edge20};
    }
    const double va = d3 * d6 - d5 * d4;
    const double e1 = d4 - d3;
    const double e2 = d5 - d6;
    if (va <= 0.0 && e1 >= 0.0 && e2 >= 0.0)
    {
        const double den = e1 + e2;
        const double t = den > 0.0 ? e1 / den : 0.0;
        const Vec3 q = b + t * (c - b);
        return {q, Vec3(0.0, 1.0 - t, t), (p - q).squaredNorm(), TriangleFeature::edge12};
    }
    // Face region. va + vb + vc = |ab x ac|^2 (Lagrange's identity); for slivers it is lost in
    // cancellation, and then the signs above are unreliable too, so only a well-conditioned,
    // in-range answer is accepted.
    const double den = va + vb + vc;
    if (den > 1e-14 * ab.squaredNorm() * ac.squaredNorm())
    {
        const double v = vb / den;
        const double w = vc / den;
        const double u = 1.0 - v - w;
        if (v >= 0.0 && w >= 0.0 && u >= 0.0)
        {
            const Vec3 q = a + v * ab + w * ac;
            return {q, Vec3(u, v, w), (p - q).squaredNorm(), TriangleFeature::face};
        }
    }
    return detail::closest_on_edges(p, a, b, c);
}

//! Squared distance only: the same region walk as closest_point_on_triangle without building
//! the point, for the many candidates of a BVH search that do not win.
inline double point_triangle_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    if (detail::has_zero_edge(ab, ac))
    {
        return detail::closest_on_edges(p, a, b, c).distance_squared;
    }
    const Vec3 ap = p - a;
    const double d1 = ab.dot(ap);
    const double d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0)
    {
        return ap.squaredNorm();
    }
    const double d00 = ab.squaredNorm();
    const double d01 = ab.dot(ac);
    const double d11 = ac.squaredNorm();
    // The dot products with p - b and p - c follow from those with p - a.
    const double d3 = d1 - d00;
    const double d4 = d2 - d01;
    if (d3 >= 0.0 && d4 <= d3)
    {
        return (ap - ab).squaredNorm();
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
    {
        const double t = d00 > 0.0 ? d1 / d00 : 0.0;
        return (ap - t * ab).squaredNorm();
    }
    const double d5 = d1 - d01;
    const double d6 = d2 - d11;
    if (d6 >= 0.0 && d5 <= d6)
    {
        return (ap - ac).squaredNorm();
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
    {
        const double t = d11 > 0.0 ? d2 / d11 : 0.0;
        return (ap - t * ac).squaredNorm();
    }
    const double va = d3 * d6 - d5 * d4;
    const double e1 = d4 - d3;
    const double e2 = d5 - d6;
    if (va <= 0.0 && e1 >= 0.0 && e2 >= 0.0)
    {
        const double t = e1 + e2 > 0.0 ? e1 / (e1 + e2) : 0.0;
        return (ap - ab - t * (ac - ab)).squaredNorm();
    }
    // va + vb + vc = |ab x ac|^2: the same well-conditioned test as in closest_point_on_triangle.
    const double den = va + vb + vc;
    if (den > 1e-14 * d00 * d11)
    {
        const double v = vb / den;
        const double w = vc / den;
        if (v >= 0.0 && w >= 0.0 && v + w <= 1.0)
        {
            // The residual vector, not |ap|^2 minus a projection: no cancellation near the face.
            return (ap - v * ab - w * ac).squaredNorm();
        }
    }
    return detail::closest_on_edges(p, a, b, c).distance_squared;
}

} // namespace zomeify
