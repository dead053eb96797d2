#pragma once
//! \file wild_corpus.h
//! Meshes as people drop them (issue 36), made in code: closed shapes with holes of 3 to 300
//! edges, pinched vertices, edges with three faces, specks, overlapping parts, open cylinders and
//! sheets, a single triangle, a point cloud. Each says what must become of it.

#include <string>
#include <vector>

#include "core/surface/polygon_soup.h"

namespace zomeify::surface_test {

struct WildMesh
{
    std::string name;
    PolygonSoup soup;
    //! Accepted: the genus of the repaired solid and words its repair list must hold. Refused: a
    //! phrase of the one-line reason (`refusal` non-empty).
    long long genus = 0;
    std::vector<std::string> repairs;
    std::string refusal;
};

//! The whole corpus, in a fixed order.
std::vector<WildMesh> wild_corpus();

//! `soup` with the faces removed whose centroid lies within `radius` of `centre` (a hole).
PolygonSoup punched(PolygonSoup soup, const Vec3& centre, double radius);

} // namespace zomeify::surface_test
