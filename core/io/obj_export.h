#pragma once
//! \file obj_export.h
//! Wavefront OBJ of the built model (balls and struts as closed triangle meshes, on the table:
//! centred in x and z, resting on y = 0, y up) with an MTL of the Zome colours. Millimetres by
//! default (a maker's unit; the header comment says so), metres on request. OBJ has no
//! instancing, so every part is written out; every vertex written is used by a face. `Kd` is
//! linear RGB, the GLB's baseColorFactor, as Blender reads it (issue 42: there the OBJ and the GLB look
//! alike); three.js's MTLLoader reads `Kd` as sRGB, so there the OBJ looks darker than the GLB.

#include <string>

#include "core/zome/model.h"

namespace zomeify {

enum class ObjUnits
{
    Millimetres,
    Metres
};

//! "mm" or "m" (the CLI's --obj-units); InvalidInputError otherwise.
ObjUnits parse_obj_units(const std::string& text);

struct ObjExport
{
    std::string obj;
    std::string mtl;
};

//! `mtl_name` is the file name the OBJ's `mtllib` line refers to.
ObjExport write_obj(const ZomeModel& model, const std::string& mtl_name, ObjUnits units = ObjUnits::Millimetres);

} // namespace zomeify
