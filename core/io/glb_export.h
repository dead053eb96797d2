#pragma once
//! \file glb_export.h
//! Binary glTF (.glb) of the built model, through tinygltf: units in millimetres, one mesh per
//! strut kind present (a cylinder of that kind's real length, in its colour) plus one ball mesh,
//! and one node per ball and per strut placing that mesh. Opens in any glTF viewer.

#include <string>

#include "core/zome/model.h"

namespace zomeify {

//! The .glb bytes.
std::string write_glb(const ZomeModel& model);

} // namespace zomeify
