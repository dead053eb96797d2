#pragma once
//! \file fidelity.h
//! How faithful a Zome model is to the input surface S, as a user sees it: distances measured both
//! ways from area-uniform random points on each surface (the model's surface is its faces, split
//! by face_triangles.h), placed by the model's transform. model→surface says where the model sticks
//! out, surface→model where it misses a part of the shape. Reported in b0 and in millimetres at
//! real size (1 b0 = 46.27 mm), with where the largest gap is.

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "core/geom/closest_point.h"
#include "core/zome/model.h"

namespace zomeify {

struct FidelityOptions
{
    //! Random points on each surface (each picks a triangle with probability proportional to its
    //! area, then a uniform point in it). Deterministic for a given seed.
    int samples_per_side = 50000;
    uint64_t seed = 1;
    //! radius > 0: only the points within `radius` of `near` (mesh units) count, on both sides (the
    //! fidelity of one spot, e.g. before and after fixing it).
    Vec3 near = Vec3::Zero();
    double radius = 0.0;
};

//! Distances from one surface's points to the other (b0).
struct OneWay
{
    double rms = 0.0;
    double max = 0.0;
    Vec3 farthest = Vec3::Zero(); //!< the point at the largest distance, in the mesh's coordinates
};

struct Fidelity
{
    OneWay model_to_surface;    //!< points of the model's faces to S
    OneWay surface_to_model;    //!< points of S to the model's faces
    double rms_symmetric = 0.0; //!< sqrt of the mean of both mean squared distances (b0)
    double hausdorff = 0.0;     //!< the larger maximum (b0)
    //! Where the Hausdorff distance is, in the mesh's coordinates, and whether it is a part of S
    //! the model misses (true) or a part of the model off S (false).
    Vec3 largest_gap_at = Vec3::Zero();
    bool gap_is_missed_surface = true;
    //! The largest gap's place in S's bounding box, in words (y up, z towards the viewer, x to the
    //! right): e.g. "top front left", "middle", "bottom right".
    std::string where;
};

//! Measures a model with faces, placed on S by model.transform (Zome units → mesh units). Throws
//! InvalidInputError if the model has no faces or no placement (scale ≤ 0).
Fidelity measure_fidelity(const ZomeModel& model, const SurfaceProjector& surface, const FidelityOptions& options = {});

//! The words for a point in a box (y up, z front, x right); "middle" at the centre.
std::string place_in_box(const Vec3& p, const Vec3& box_min, const Vec3& box_max);

//! place_in_box() in the bounding box of `surface`'s vertices.
std::string place_on_surface(const Vec3& p, const TriangleMesh& surface);

//! The figures as JSON: both ways' RMS and maximum, the symmetric RMS and Hausdorff distance, in
//! b0 and mm, and where the largest gap is (the --stats and score --json "fidelity" object).
nlohmann::json fidelity_json(const Fidelity& f);

//! One line for users: "largest gap 24 mm (0.52 b0), the model misses the surface at the top front
//! left; typical distance 5.1 mm (RMS 0.11 b0)".
std::string fidelity_summary(const Fidelity& f);

} // namespace zomeify
