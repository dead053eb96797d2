#pragma once
//! \file geom_reference.h
//! Slow, independent references for the geom tests: closest point by plane projection plus edge
//! segments (no Voronoi-region walk), brute force over all triangles, and inside/outside by ray
//! parity over several random directions with a majority vote.

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/geom/triangle_mesh.h"

namespace zomeify::test {

//! Squared distance from p to triangle (a, b, c), by plane projection and edge segments.
double reference_triangle_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

//! Smallest squared distance from p to any triangle of `mesh`.
double brute_force_distance_squared(const TriangleMesh& mesh, const Vec3& p);

//! Inside by ray parity: the majority over `rays` random directions (odd) of the parity of the
//! number of triangles each ray crosses.
bool ray_parity_inside(const TriangleMesh& mesh, const Vec3& p, int rays = 5, uint32_t seed = 7);

//! Diagonal of the mesh's bounding box.
double bbox_diagonal(const TriangleMesh& mesh);

//! Uniform random point in the mesh's bounding box grown by `margin` times its diagonal.
Vec3 random_point_in_box(const TriangleMesh& mesh, double margin, std::mt19937& rng);

//! A random point on the surface (area-weighted) moved by a random vector of length below `radius`.
Vec3 random_point_near_surface(const TriangleMesh& mesh, double radius, std::mt19937& rng);

//! Signed volume (positive for a closed mesh oriented outward).
double signed_volume(const TriangleMesh& mesh);

//! The shared meshes (ZOME_SHARED_DIR/data/meshes/*.obj), by file name.
std::vector<std::string> shared_mesh_names();
std::string shared_mesh_path(const std::string& name);

} // namespace zomeify::test
