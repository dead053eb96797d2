#pragma once
//! \file geom_fixtures.h
//! Procedural closed input surfaces for the geom tests: 2-manifolds with faces counter-clockwise
//! seen from outside, like core/surface's output.

#include <string>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify::test {

//! UV sphere of `radius` at the origin: `rings` latitude bands (>= 2), `segments` longitudes (>= 3).
TriangleMesh make_uv_sphere(double radius, int rings, int segments);

//! Icosahedron subdivided `levels` times, vertices pushed onto the sphere of `radius`.
TriangleMesh make_icosphere(double radius, int levels);

//! Torus around the y axis: tube centre circle of radius `major`, tube radius `minor`.
TriangleMesh make_torus(double major, double minor, int major_segments, int minor_segments);

//! Axis-aligned cube [-half, half]^3, each face split into n x n quads of two triangles.
TriangleMesh make_cube(double half, int n);

//! A named mesh, for parameterised tests.
struct NamedMesh
{
    std::string name;
    TriangleMesh mesh;
};

//! Sphere, icosphere, torus and cube at moderate resolutions, shifted away from the origin.
std::vector<NamedMesh> procedural_surfaces();

} // namespace zomeify::test
