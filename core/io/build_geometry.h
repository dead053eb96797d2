#pragma once
//! \file build_geometry.h
//! What a built model looks like, for the exporters: real sizes in millimetres (ball 17.673 mm
//! across, strut lengths node centre to node centre), Zome colours, and one placement per ball
//! and per strut. Strut thickness is approximate (the real struts are not round).
//!
//! The placements are "on the table": the model is centred in x and z and rests on y = 0 (its
//! lowest ball touches the floor), y up, so that viewers and slicers show it where they expect.

#include <array>
#include <cstdint>
#include <vector>

#include "core/zome/model.h"
#include "core/zome/slots.h"

namespace zomeify {

struct SimpleMesh
{
    std::vector<std::array<float, 3>> positions;
    std::vector<std::array<float, 3>> normals;
    std::vector<uint32_t> indices; //!< triangles, counter-clockwise from outside
};

//! A closed cylinder along +Y from y = 0 to y = length.
SimpleMesh make_cylinder(float radius, float length, int sides);
//! A UV sphere centred at the origin: one vertex per pole and no seam, so it is closed and every
//! vertex is used (2 + (stacks − 1)·slices vertices).
SimpleMesh make_sphere(float radius, int slices, int stacks);

//! sRGB colour (0..1) of a strut colour and of the white balls: the colour as a screen shows it.
std::array<float, 3> zome_color_srgb(Color c);
std::array<float, 3> ball_color_srgb();
//! The same in linear RGB: what glTF's baseColorFactor and OBJ's `Kd` hold (Blender reads `Kd` as linear).
std::array<float, 3> zome_color_linear(Color c);
std::array<float, 3> ball_color_linear();

inline constexpr float kStrutRadiusMm = 3.0f;

struct Placement
{
    std::array<float, 3> translation; //!< mm
    std::array<float, 4> rotation;    //!< unit quaternion x, y, z, w taking +Y to the strut
    uint32_t index = 0;               //!< the ball's or strut's index in the model
};

struct BuildGeometry
{
    std::vector<std::array<float, 3>> ball_centres;                     //!< mm, on the table
    std::array<std::vector<Placement>, kStrutKindCount> struts_by_kind; //!< per StrutKind
    std::array<double, 3> size_mm{};  //!< extent of the balls (centres ± radius), x/y/z
    std::array<double, 3> shift_mm{}; //!< what was added to the model's own coordinates (in mm)
};

//! Placements of every ball and strut, centred on the table (InvalidInputError if a strut is
//! not a Zome vector).
BuildGeometry build_geometry(const ZomeModel& model);

//! Applies a placement to a point of a template mesh.
std::array<float, 3> place(const Placement& p, const std::array<float, 3>& v);

} // namespace zomeify
