#pragma once
//! \file glb_export.h
//! Binary glTF (.glb) of the built model, through tinygltf, at real size in metres (glTF's unit),
//! y up, on the table (centred in x and z, resting on y = 0): one mesh per strut kind present (a
//! cylinder of that kind's real length, in its colour) plus one ball mesh, and one node per ball
//! and per strut placing that mesh, named after its part and index ("PST-B1-BLU strut 12",
//! "PZB-BAL-W ball 3"). Opens in any glTF viewer and in Blender at the right size.

#include <string>

#include "core/zome/model.h"

namespace zomeify {

//! The .glb bytes.
std::string write_glb(const ZomeModel& model);

} // namespace zomeify
