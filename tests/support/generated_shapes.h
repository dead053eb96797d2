#pragma once
//! \file generated_shapes.h
//! Closed test surfaces made in code (issue 37) whose holes and gaps are known by construction: a
//! knotted tube whose strands pass closer to each other than the tube is thick, a genus-2 double
//! torus, and a mug whose handle is about one cell thick at the default grid (8 cells). Each is the zero set
//! of a distance function, polygonised by marching tetrahedra (a closed, outward 2-manifold).

#include <functional>
#include <string>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify::test {

struct GeneratedShape
{
    std::string name;
    TriangleMesh mesh;
    long long genus = 0;
    double longest_side = 0.0;  //!< of the bounding box, mesh units
    double thinnest = 0.0;      //!< thickness of the thinnest part (tube or handle diameter), mesh units
    double narrowest_gap = 0.0; //!< the narrowest gap between parts of the surface (strands, a hole), mesh units
};

//! The zero set of `distance` (negative inside) over [lo, hi] on a grid of `cells` along the longest
//! side, by marching tetrahedra (six per cube, Kuhn's split, so neighbours agree).
TriangleMesh polygonise(const std::function<double(const Vec3&)>& distance, const Vec3& lo, const Vec3& hi, int cells);

//! A trefoil tube: strands pass `gap_over_thickness` tube diameters apart at their closest.
GeneratedShape make_trefoil_tube(double gap_over_thickness = 0.5);
//! Two solid tori side by side, joined where their tubes meet: genus 2.
GeneratedShape make_double_torus();
//! A mug (open cup) with a handle of diameter longest side / `handle_cells` (one cell at that grid).
GeneratedShape make_mug(double handle_cells = 8.0);

//! A car (issue 41): a body with a cabin and four wheels, mirror-symmetric about z = 0 (length
//! along x, height along y); genus 0. Not in generated_shapes() (the tests over those do not need it).
GeneratedShape make_car();

//! The three, built once per process.
const std::vector<GeneratedShape>& generated_shapes();

} // namespace zomeify::test
