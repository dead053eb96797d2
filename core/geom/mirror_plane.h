#pragma once
//! \file mirror_plane.h
//! The best mirror plane of a surface S and how symmetric S is about it (issue 41, item 1): the
//! plane n·x = offset for which the mirror image of S lies closest to S.
//!
//! For a reflection R (an isometry and its own inverse) the distance from R(S) to S at R(p) equals
//! the distance from S to R(S) at p, so one set of points measures both directions: the points p
//! spread evenly over S, each scored by d(R(p), S).

#include "core/geom/closest_point.h"
#include "core/geom/triangle_mesh.h"

namespace zomeify {

struct MirrorPlane
{
    Vec3 normal = Vec3::UnitX(); //!< unit
    double offset = 0.0;         //!< the plane is {x : normal·x = offset}
    //! d(R(p), S) over points p spread evenly over S (mesh units): root mean square, 95th
    //! percentile and largest.
    double rms = 0.0, p95 = 0.0, max = 0.0;
    //! The surface's bounding-box diagonal (mesh units), for relative figures.
    double diagonal = 0.0;

    Vec3 reflect(const Vec3& p) const { return p - 2.0 * (normal.dot(p) - offset) * normal; }
};

struct MirrorPlaneOptions
{
    int search_points = 1500; //!< points scoring each candidate plane
    int final_points = 20000; //!< points measuring the plane found
};

//! The plane found by scoring candidate normals through the area centroid (the principal axes,
//! the coordinate axes, 128 directions spread over a hemisphere), then refining the best few by
//! shrinking turns of the normal and shifts of the plane. Deterministic (no random numbers: the
//! points are a low-discrepancy sequence over the triangles' areas). Throws InvalidInputError for
//! a surface without area.
MirrorPlane find_mirror_plane(const SurfaceProjector& surface, const MirrorPlaneOptions& options = {});

//! The same figures for a given plane (normal need not be unit; it is normalised).
MirrorPlane measure_mirror_plane(const SurfaceProjector& surface, const Vec3& normal, double offset,
                                 int points = 20000);

} // namespace zomeify
