#pragma once
//! \file surface_fixtures.h
//! Small input surfaces built in code, and writers for every format the readers accept, so that
//! tests need no committed fixture files.

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "core/surface/polygon_soup.h"

namespace zomeify::surface_test {

//! The axis-aligned cube [0,1]^3 shifted by `offset`, as 6 outward quads (8 vertices).
PolygonSoup cube_quads(const Vec3& offset = Vec3::Zero());
//! The same cube as 12 outward triangles.
PolygonSoup cube_triangles(const Vec3& offset = Vec3::Zero());
//! A prism over a regular pentagon: 2 pentagons and 5 quads, 10 vertices.
PolygonSoup pentagonal_prism();
//! A prism over an L-shaped (non-convex) hexagon: 2 hexagons and 6 quads, 12 vertices.
PolygonSoup l_prism();
//! Both soups in one (indices of `b` shifted).
PolygonSoup merge(const PolygonSoup& a, const PolygonSoup& b);
//! Every polygon reversed.
PolygonSoup reversed(PolygonSoup soup);

//! Signed volume of a closed, triangulated surface.
double signed_volume(const TriangleMesh& mesh);

std::string to_obj(const PolygonSoup& soup);
std::string to_off(const PolygonSoup& soup);
//! Triangles only (fan-split polygons), each with its own three vertices.
std::string to_stl_ascii(const PolygonSoup& soup);
std::string to_stl_binary(const PolygonSoup& soup, const std::string& header80 = "zomeify test");
enum class PlyEncoding
{
    ascii,
    little_endian,
    big_endian
};
//! With extra properties and an extra element the reader must skip: vertex x (float) y (double)
//! z (short, so coordinates must be integers there), a uchar "quality"; face list uchar/int
//! (or ushort/uint with `wide_lists`) plus a float; an "edge" element after the faces.
std::string to_ply(const PolygonSoup& soup, PlyEncoding encoding, bool wide_lists = false);
//! GLB or glTF (data: URI buffers) written with tinygltf: one mesh, one node with `matrix`
//! (column-major 4x4, empty for none).
std::string to_gltf(const PolygonSoup& soup, bool binary, const std::vector<double>& matrix = {});

std::span<const uint8_t> bytes_of(const std::string& s);

//! The message of the InvalidInputError `f` throws; fails the test (and returns "") if it throws
//! nothing or something else.
std::string invalid_input_message(const std::function<void()>& f);

} // namespace zomeify::surface_test
