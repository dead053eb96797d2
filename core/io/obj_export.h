#pragma once
//! \file obj_export.h
//! Wavefront OBJ of the built model (balls and struts as triangle meshes, millimetres) with an
//! MTL of the Zome colours. OBJ has no instancing, so every part is written out.

#include <string>

#include "core/zome/model.h"

namespace zomeify {

struct ObjExport
{
    std::string obj;
    std::string mtl;
};

//! `mtl_name` is the file name the OBJ's `mtllib` line refers to.
ObjExport write_obj(const ZomeModel& model, const std::string& mtl_name);

} // namespace zomeify
