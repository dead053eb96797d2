#pragma once
//! \file report_text.h
//! A SurfaceReport as text: the table `zomeify inspect` prints and the JSON of `inspect --json`
//! (also what the page shows after a file is dropped).

#include <string>

#include "core/surface/prepare.h"

namespace zomeify {

//! A two-column, human-readable table; `name` is the input's file name.
std::string surface_report_table(const SurfaceReport& report, const std::string& name);

//! Pretty-printed JSON object (with a trailing newline). Keys: file, ok, vertices, faces, edges,
//! closed, manifold, components, cavities, genus, euler, holes, boundary_edges, non_manifold_edges,
//! non_manifold_vertices, non_orientable_components, bbox {min, max, diagonal},
//! input {vertices, faces}, repairs {welded_vertices, ...}, repaired [lines], problems [lines].
std::string surface_report_json(const SurfaceReport& report, const std::string& name);

} // namespace zomeify
