#pragma once
//! \file triangle_estimate.h
//! The distance estimate of a TriangleBlock, in 4-wide float vectors. Include it only from
//! sources compiled with the project's SIMD flags (closest_point.cpp): under Emscripten, functions
//! taking vectors by value must not be emitted with and without -msimd128 in different objects.

#include <cfloat>

#include "core/geom/simd4.h"
#include "core/geom/triangle_block.h"

namespace zomeify {

namespace detail {

//! (n × e) · v = n · (e × v), lane-wise.
inline simd::F4 triple(simd::F4 nx, simd::F4 ny, simd::F4 nz, simd::F4 ex, simd::F4 ey, simd::F4 ez, simd::F4 vx,
                       simd::F4 vy, simd::F4 vz)
{
    return nx * (ey * vz - ez * vy) + ny * (ez * vx - ex * vz) + nz * (ex * vy - ey * vx);
}

//! Squared distance from v (relative to the segment's start) to the segment [0, e] of squared
//! length `len2`; a zero-length segment measures to its start.
inline simd::F4 segment_distance_squared(simd::F4 vx, simd::F4 vy, simd::F4 vz, simd::F4 ex, simd::F4 ey, simd::F4 ez,
                                         simd::F4 len2)
{
    const simd::F4 t = simd::min(
        simd::max(simd::dot(vx, vy, vz, ex, ey, ez) / simd::max(len2, simd::splat(FLT_MIN)), simd::splat(0.0f)),
        simd::splat(1.0f));
    const simd::F4 rx = vx - t * ex;
    const simd::F4 ry = vy - t * ey;
    const simd::F4 rz = vz - t * ez;
    return simd::dot(rx, ry, rz, rx, ry, rz);
}

} // namespace detail

//! Estimated squared distances from p (relative to the block's origin, as floats) to the four
//! triangles. With inside_margin2 = (kInsideMargin · M)², each estimate's square root is within
//! kSlack · M of the exact distance: a point strictly over the face (by the margin) is measured to
//! the plane, any other point to the nearest edge segment, which is within twice the margin of the
//! truth for points over the face near an edge. No branches; no NaN for finite input.
inline simd::F4 estimate_distances_squared(const TriangleBlock& t, simd::F4 px, simd::F4 py, simd::F4 pz,
                                           simd::F4 inside_margin2)
{
    using simd::F4;
    const F4 apx = px - t.ax;
    const F4 apy = py - t.ay;
    const F4 apz = pz - t.az;
    const F4 bpx = apx - t.abx;
    const F4 bpy = apy - t.aby;
    const F4 bpz = apz - t.abz;
    const F4 bcx = t.acx - t.abx;
    const F4 bcy = t.acy - t.aby;
    const F4 bcz = t.acz - t.abz;
    const F4 len_ab = simd::dot(t.abx, t.aby, t.abz, t.abx, t.aby, t.abz);
    const F4 len_bc = simd::dot(bcx, bcy, bcz, bcx, bcy, bcz);
    const F4 len_ca = simd::dot(t.acx, t.acy, t.acz, t.acx, t.acy, t.acz);

    // (n × edge) · (p − edge start) is the in-plane distance to the edge's line times its length,
    // positive on the inner side (corners counter-clockwise about n). Edge c→a is −ac from c; its
    // line passes through a as well.
    const F4 s_ab = detail::triple(t.nx, t.ny, t.nz, t.abx, t.aby, t.abz, apx, apy, apz);
    const F4 s_bc = detail::triple(t.nx, t.ny, t.nz, bcx, bcy, bcz, bpx, bpy, bpz);
    const F4 s_ca = -detail::triple(t.nx, t.ny, t.nz, t.acx, t.acy, t.acz, apx, apy, apz);
    const F4 zero = simd::splat(0.0f);
    const simd::I4 over_face = (s_ab > zero) & (s_ab * s_ab > inside_margin2 * len_ab) & (s_bc > zero) &
                               (s_bc * s_bc > inside_margin2 * len_bc) & (s_ca > zero) &
                               (s_ca * s_ca > inside_margin2 * len_ca);

    const F4 h = simd::dot(t.nx, t.ny, t.nz, apx, apy, apz);
    const F4 d_ab = detail::segment_distance_squared(apx, apy, apz, t.abx, t.aby, t.abz, len_ab);
    const F4 d_bc = detail::segment_distance_squared(bpx, bpy, bpz, bcx, bcy, bcz, len_bc);
    const F4 d_ca = detail::segment_distance_squared(apx, apy, apz, t.acx, t.acy, t.acz, len_ca);
    return over_face ? h * h : simd::min(d_ab, simd::min(d_bc, d_ca));
}

} // namespace zomeify
