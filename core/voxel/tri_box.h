#pragma once
//! \file tri_box.h
//! Triangle / axis-aligned box overlap by the separating axis theorem (13 axes: the 3 box normals,
//! the triangle normal, and the 9 cross products of triangle edges with box axes).

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! How the box boundary counts.
enum class BoxContact
{
    Closed, //!< the closed box: a triangle that only touches the box's boundary overlaps it
    Open,   //!< the open box: the triangle must reach the box's interior
};

//! True if triangle (a, b, c) meets the box centre ± half (half > 0 per axis).
//! A degenerate triangle (a segment or a point) is handled: the axes that vanish are skipped.
bool triangle_box_overlap(const Vec3& centre, const Vec3& half, const Vec3& a, const Vec3& b, const Vec3& c,
                          BoxContact contact);

} // namespace zomeify
