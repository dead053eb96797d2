#pragma once
//! \file vef.h
//! vZome's exact VEF format (design.md §4). Tokens are separated by whitespace; `(a,b)` means
//! a·φ + b. Layout: `vZome VEF <version> field golden`, vertex count, W X Y Z per vertex, edge
//! count and pairs, face count and `k i1 … ik` rows, ball count and vertex indices.
//!
//! vZome's raw scale is 2φ² raw units per b0. Some files are drawn at another power of φ (the
//! paper's bunny at 2φ³), so the reader picks the φ-power at which every strut is one of the
//! nine strut kinds, preferring vZome's own scale, then the nearest powers.

#include <string>
#include <string_view>

#include "core/zome/model.h"

namespace zomeify {

struct VefReadInfo
{
    int phi_power = 2;  //!< the file's scale is 2φ^phi_power raw units per b0
    int version = 0;    //!< the VEF version number in the header
    size_t balls = 0;   //!< entries of the ball list
};

ZomeModel read_vef(std::string_view text, VefReadInfo* info = nullptr);
ZomeModel read_vef_file(const std::string& path, VefReadInfo* info = nullptr);

//! Writes at vZome's raw scale, with faces if the model has them and every node as a ball.
std::string write_vef(const ZomeModel& model);

} // namespace zomeify
