#pragma once
//! \file polygon_soup.h
//! What every mesh reader produces: positions plus polygons of any size, as written in the file.
//! Nothing is checked or repaired here; `prepare.h` turns a soup into a closed triangle mesh.

#include <cstdint>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! Flat vertex positions and index polygons (any size, including faces with fewer than 3 vertices,
//! which the readers keep so that the diagnosis can count them).
struct PolygonSoup
{
    std::vector<Vec3> positions;
    std::vector<std::vector<uint32_t>> polygons;
};

} // namespace zomeify
