#pragma once
//! \file point_arg.h
//! A point given on the command line as "X,Y,Z" (mesh units), e.g. `--near 1.5,-2,0.25`.

#include <string>

#include "core/geom/triangle_mesh.h"

namespace zomeify::cli {

//! The point of `text`; InvalidInputError naming `flag` when it is not three finite numbers.
Vec3 point_of(const std::string& text, const std::string& flag);

} // namespace zomeify::cli
