#pragma once
//! \file clearance.h
//! The distances by which real parts are kept apart (core/zome/clearance_rules.h): point to
//! segment (a ball centre to a strut axis), segment to segment (two strut axes), and whether a
//! segment meets a triangle (a strut through a face, measured by its canonical triangles,
//! core/mesh/face_triangles.h). Pure geometry on Vec3: inline, allocation-free and noexcept, for
//! the whole-model checker (core/parts/clashes.h) and the annealer's per-commit checks alike.
//!
//! **Same answer in any argument order.** Each function puts its arguments in a canonical order
//! (the ends of a segment, the two segments, the corners of a triangle, lexicographically) before
//! computing, so swapping the ends of a strut or the two struts gives a bit-identical result: an
//! incremental check and a whole-model check that meet the same pair from different sides agree.
//!
//! **Degenerate input.** Zero-length segments are points, parallel and collinear segments are
//! handled exactly (the closest pair then involves an end point), zero-area triangles are their
//! edges. Nothing divides by zero and no NaN is produced from finite input.
//!
//! At the end, the four rules themselves on positions in b0 (balls_clash, ball_strut_clash,
//! struts_clash, strut_face_clash): callers that check part of a model and the whole-model check
//! compare the same numbers with the same thresholds.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include <Eigen/Geometry>

#include "core/geom/point_triangle.h"
#include "core/geom/triangle_mesh.h"
#include "core/zome/clearance_rules.h"

namespace zomeify {

//! The closest points of two segments [p0, p1] and [q0, q1]: p0 + s·(p1 − p0) and q0 + t·(q1 − q0).
struct SegmentClosest
{
    double s = 0.0;                //!< in [0, 1] along the first segment
    double t = 0.0;                //!< in [0, 1] along the second segment
    double distance_squared = 0.0; //!< squared distance between the two points
};

//! segment_intersects_triangle() counts a segment within this fraction of the largest coordinate
//! magnitude of its arguments from the triangle as touching it. Coordinates of exact lattice
//! points are rounded to double, so "exactly touching" or "exactly coplanar" is only known up to a
//! few units in the last place; 1e-12 leaves a margin of several thousand of them and is far below
//! any size that matters (1e-9 b0 for a model 1000 b0 across).
inline constexpr double kTouchTolerance = 1e-12;

namespace detail {

//! Lexicographic order of points: the canonical order of ends and corners.
inline bool lex_less(const Vec3& a, const Vec3& b) noexcept
{
    if (a.x() != b.x())
        return a.x() < b.x();
    if (a.y() != b.y())
        return a.y() < b.y();
    return a.z() < b.z();
}

//! t clamped to [0, 1]; NaN becomes 0.
inline double clamp01(double t) noexcept { return t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0; }

//! Closest point of segment [a, b] to p as its parameter and squared distance. The residual is
//! measured from the nearer named point (a or b at the clamps), so answers at the ends are exact
//! differences.
inline SegmentClosest point_segment(const Vec3& p, const Vec3& a, const Vec3& b) noexcept
{
    const Vec3 ab = b - a;
    const Vec3 ap = p - a;
    const double len2 = ab.squaredNorm();
    const double along = ap.dot(ab);
    if (!(along > 0.0) || !(len2 > 0.0))
        return {0.0, 0.0, ap.squaredNorm()};
    if (along >= len2)
        return {1.0, 0.0, (p - b).squaredNorm()};
    const double t = along / len2;
    return {t, 0.0, (ap - t * ab).squaredNorm()};
}

//! segment_segment_closest() on arguments already in canonical order. The squared distance over
//! (s, t) in [0, 1]² is convex, so its minimum is either the critical point of the two lines
//! (when it lies inside the square) or on the square's border, where one parameter is 0 or 1:
//! an end of one segment against the other segment. Taking the smallest of the four end
//! candidates and the interior one is exact for parallel, collinear and zero-length segments (no
//! interior critical point is needed there) and never divides by zero. Every candidate is the
//! distance of two actual points of the segments, so a rounding error in (s, t) can only make a
//! candidate larger, never report a distance smaller than the true one.
inline SegmentClosest closest_canonical(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) noexcept
{
    SegmentClosest best = point_segment(p0, q0, q1);
    best.t = best.s;
    best.s = 0.0;
    const auto consider = [&best](double s, double t, double d2) {
        if (d2 < best.distance_squared)
            best = {s, t, d2};
    };
    const SegmentClosest e1 = point_segment(p1, q0, q1);
    consider(1.0, e1.s, e1.distance_squared);
    const SegmentClosest e2 = point_segment(q0, p0, p1);
    consider(e2.s, 0.0, e2.distance_squared);
    const SegmentClosest e3 = point_segment(q1, p0, p1);
    consider(e3.s, 1.0, e3.distance_squared);

    const Vec3 d1 = p1 - p0;
    const Vec3 d2 = q1 - q0;
    const Vec3 r = p0 - q0;
    // |d1 × d2|² = |d1|²|d2|² − (d1·d2)², without the cancellation of the right-hand side.
    const double den = d1.cross(d2).squaredNorm();
    if (den > 0.0)
    {
        const double a = d1.squaredNorm(), b = d1.dot(d2), e = d2.squaredNorm();
        const double c = d1.dot(r), f = d2.dot(r);
        const double s = (b * f - c * e) / den;
        const double t = (a * f - b * c) / den;
        if (s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0)
            consider(s, t, (r + s * d1 - t * d2).squaredNorm());
    }
    return best;
}

//! The largest absolute coordinate: the magnitude that sets the rounding of the inputs.
inline double max_abs_coordinate(const Vec3& a) noexcept
{
    return std::max({std::abs(a.x()), std::abs(a.y()), std::abs(a.z())});
}

} // namespace detail

//! Squared distance from p to the closed segment [a, b] (|p − a|² when a = b).
inline double point_segment_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b) noexcept
{
    return detail::lex_less(b, a) ? detail::point_segment(p, b, a).distance_squared
                                  : detail::point_segment(p, a, b).distance_squared;
}

//! The closest points of the closed segments [p0, p1] and [q0, q1] (either may have zero length).
//! When several pairs are closest (parallel overlapping segments), one of them.
inline SegmentClosest segment_segment_closest(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) noexcept
{
    const bool flip_p = detail::lex_less(p1, p0);
    const bool flip_q = detail::lex_less(q1, q0);
    const Vec3& pa = flip_p ? p1 : p0;
    const Vec3& pb = flip_p ? p0 : p1;
    const Vec3& qa = flip_q ? q1 : q0;
    const Vec3& qb = flip_q ? q0 : q1;
    const bool swap = detail::lex_less(qa, pa) || (qa == pa && detail::lex_less(qb, pb));
    SegmentClosest r = swap ? detail::closest_canonical(qa, qb, pa, pb) : detail::closest_canonical(pa, pb, qa, qb);
    if (swap)
        std::swap(r.s, r.t);
    if (flip_p)
        r.s = 1.0 - r.s;
    if (flip_q)
        r.t = 1.0 - r.t;
    return r;
}

//! Squared distance between the closed segments [p0, p1] and [q0, q1] (the axis-to-axis distance
//! of two struts); exact for parallel and collinear segments, and for zero-length ones.
inline double segment_segment_distance_squared(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) noexcept
{
    return segment_segment_closest(p0, p1, q0, q1).distance_squared;
}

//! Whether the closed segment [p, q] and the closed triangle (a, b, c) have a point in common,
//! touching included: an end on the triangle, the segment through an edge or a corner, or lying
//! in the triangle's plane across it. Any orientation of the corners; a degenerate triangle is
//! its edges. A configuration within kTouchTolerance × (largest coordinate magnitude) of touching
//! counts as touching, so exactly coplanar or exactly touching lattice configurations are found
//! although their coordinates are rounded. Callers exclude a strut and a face that share a ball
//! (they touch there by construction).
inline bool segment_intersects_triangle(const Vec3& p_in, const Vec3& q_in, const Vec3& a_in, const Vec3& b_in,
                                        const Vec3& c_in) noexcept
{
    using detail::lex_less;
    const bool flip = lex_less(q_in, p_in);
    const Vec3& p = flip ? q_in : p_in;
    const Vec3& q = flip ? p_in : q_in;
    const Vec3* x = &a_in;
    const Vec3* y = &b_in;
    const Vec3* z = &c_in;
    if (lex_less(*y, *x))
        std::swap(x, y);
    if (lex_less(*z, *y))
        std::swap(y, z);
    if (lex_less(*y, *x))
        std::swap(x, y);
    const Vec3& a = *x;
    const Vec3& b = *y;
    const Vec3& c = *z;

    using detail::max_abs_coordinate;
    const double scale = std::max({max_abs_coordinate(p), max_abs_coordinate(q), max_abs_coordinate(a),
                                   max_abs_coordinate(b), max_abs_coordinate(c)});
    const double tol = kTouchTolerance * scale;
    const double tol2 = tol * tol;

    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    const Vec3 n = ab.cross(ac);
    const double twice_area = n.norm();
    const double longest2 = std::max({ab.squaredNorm(), ac.squaredNorm(), (c - b).squaredNorm()});
    // The plane is only trusted when every angle of the triangle has a sine above 0.01 (its normal
    // is then accurate to a few hundred units in the last place); slivers go to the distance test.
    if (twice_area > 0.01 * longest2)
    {
        const double dp = n.dot(p - a) / twice_area; // signed distances to the plane
        const double dq = n.dot(q - a) / twice_area;
        if ((dp > tol && dq > tol) || (dp < -tol && dq < -tol))
            return false;
        if (std::abs(dp) > tol || std::abs(dq) > tol)
        {
            // The segment meets the plane at one point (dp ≠ dq here).
            const Vec3 pq = q - p;
            const Vec3 hit = p + detail::clamp01(dp / (dp - dq)) * pq;
            const double d2 = point_triangle_distance_squared(hit, a, b, c);
            if (d2 <= tol2)
                return true;
            // Far from the triangle: even a segment at a grazing angle α cannot come within tol of
            // it (it rises tol within tol/sin α of the hit point, whose own error is below that).
            const double inv_sin = pq.norm() / std::abs(dp - dq);
            const double reach = 2.0 * tol * (1.0 + inv_sin);
            if (d2 > reach * reach)
                return false;
        }
    }
    // Within tol of the plane (coplanar), a sliver, or a near miss at a grazing angle: the segment
    // meets the closed triangle if it comes within tol of one of its edges or has an end on it.
    return point_triangle_distance_squared(p, a, b, c) <= tol2 || point_triangle_distance_squared(q, a, b, c) <= tol2 ||
           segment_segment_distance_squared(p, q, a, b) <= tol2 ||
           segment_segment_distance_squared(p, q, b, c) <= tol2 || segment_segment_distance_squared(p, q, a, c) <= tol2;
}

//! \name The clash rules (core/zome/clearance_rules.h) on positions in b0
//! A pair clashes when its distance is strictly below the minimum; callers pass only the pairs a
//! rule applies to (a strut and the balls it holds, struts or a strut and a face sharing a ball
//! are never measured).
//!@{
inline constexpr double kMinBallBallSquared = kMinBallBall * kMinBallBall;
inline constexpr double kMinBallStrutSquared = kMinBallStrut * kMinBallStrut;
inline constexpr double kMinStrutStrutSquared = kMinStrutStrut * kMinStrutStrut;

//! Two ball centres closer than kMinBallBall.
inline bool balls_clash(const Vec3& a, const Vec3& b) noexcept { return (a - b).squaredNorm() < kMinBallBallSquared; }

//! A ball centre closer than kMinBallStrut to the axis [s0, s1] of a strut it does not hold.
inline bool ball_strut_clash(const Vec3& ball, const Vec3& s0, const Vec3& s1) noexcept
{
    return point_segment_distance_squared(ball, s0, s1) < kMinBallStrutSquared;
}

//! Two strut axes [p0, p1] and [q0, q1] sharing no ball closer than kMinStrutStrut.
inline bool struts_clash(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) noexcept
{
    return segment_segment_distance_squared(p0, p1, q0, q1) < kMinStrutStrutSquared;
}

//! A strut axis [p, q] meeting a face that shares no ball with it; `triangles` are the face's
//! canonical triangles (core/mesh/face_triangles.h, one for a triangle, two for a quad).
inline bool strut_face_clash(const Vec3& p, const Vec3& q, std::span<const std::array<Vec3, 3>> triangles) noexcept
{
    for (const std::array<Vec3, 3>& t : triangles)
        if (segment_intersects_triangle(p, q, t[0], t[1], t[2]))
            return true;
    return false;
}
//!@}

} // namespace zomeify
