#pragma once
//! \file clearance.h
//! Distances between the parts of a model seen as points (ball centres), segments (strut axes)
//! and triangles (faces): what the clearance rules (core/zome/clearance_rules.h) are measured
//! with. Inline, allocation-free, for the annealer's commit checks.

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! Squared distance from p to the segment [a, b] (a point if a = b).
inline double point_segment_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b) noexcept
{
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + t * ab)).squaredNorm();
}

//! Squared distance between the segments [p0, p1] and [q0, q1] (parallel and zero-length ones
//! included): the closest pair of points, clamped to both segments.
inline double segment_segment_distance_squared(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) noexcept
{
    const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    constexpr double kTiny = 1e-18;
    if (a <= kTiny && e <= kTiny)
        return r.squaredNorm();
    if (a <= kTiny)
        return point_segment_distance_squared(p0, q0, q1);
    if (e <= kTiny)
        return point_segment_distance_squared(q0, p0, p1);
    const double c = d1.dot(r), b = d1.dot(d2);
    const double denom = a * e - b * b;
    // Parallel (denom ≈ 0): any s works; take s = 0 and let t follow.
    double s = denom > 1e-12 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
    double t = (b * s + f) / e;
    if (t < 0.0)
    {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
    }
    else if (t > 1.0)
    {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
    }
    return ((p0 + s * d1) - (q0 + t * d2)).squaredNorm();
}

//! Whether the closed segment [a, b] meets the closed triangle (t0, t1, t2), touching included
//! (within 1e-9 of the triangle's size). A segment in the triangle's plane meets it when it
//! crosses an edge or has an end inside.
inline bool segment_intersects_triangle(const Vec3& a, const Vec3& b, const Vec3& t0, const Vec3& t1,
                                        const Vec3& t2) noexcept
{
    const Vec3 e1 = t1 - t0, e2 = t2 - t0;
    const Vec3 n = e1.cross(e2);
    const double area2 = n.squaredNorm();
    if (!(area2 > 0.0))
    {
        // A degenerate triangle is a segment (or a point): meets if the segments touch.
        const double scale = std::max({e1.squaredNorm(), e2.squaredNorm(), (t2 - t1).squaredNorm()});
        const double eps = 1e-18 * std::max(scale, 1.0);
        return segment_segment_distance_squared(a, b, t0, t1) <= eps ||
               segment_segment_distance_squared(a, b, t1, t2) <= eps ||
               segment_segment_distance_squared(a, b, t2, t0) <= eps;
    }
    const double length = std::sqrt(area2);
    const double eps = 1e-9 * std::sqrt(std::max({e1.squaredNorm(), e2.squaredNorm(), 1e-300}));
    const double da = n.dot(a - t0) / length, db = n.dot(b - t0) / length;
    // Barycentric inside test of a point in the plane, with a small tolerance.
    const auto inside = [&](const Vec3& x) {
        const Vec3 w = x - t0;
        const double u = n.dot(w.cross(e2)) / area2, v = n.dot(e1.cross(w)) / area2;
        constexpr double kTol = 1e-9;
        return u >= -kTol && v >= -kTol && u + v <= 1.0 + kTol;
    };
    if ((da > eps && db > eps) || (da < -eps && db < -eps))
        return false;
    if (std::abs(da) <= eps && std::abs(db) <= eps)
    {
        // In the plane: an end inside, or a crossing with an edge.
        const double touch = eps * eps;
        return inside(a) || inside(b) || segment_segment_distance_squared(a, b, t0, t1) <= touch ||
               segment_segment_distance_squared(a, b, t1, t2) <= touch ||
               segment_segment_distance_squared(a, b, t2, t0) <= touch;
    }
    const double t = std::clamp(da / (da - db), 0.0, 1.0);
    return inside(a + t * (b - a));
}

} // namespace zomeify
