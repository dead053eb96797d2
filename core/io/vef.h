#pragma once
//! \file vef.h
//! vZome's exact VEF format (design.md §4). Tokens are separated by whitespace; `(a,b)` means
//! a·φ + b. Layout: `vZome VEF <version> field golden`, vertex count, W X Y Z per vertex, edge
//! count and pairs, face count and `k i1 … ik` rows, ball count and vertex indices.
//!
//! The reader accepts what vZome writes (VEF versions 6 to 10): `field golden` (or `polygon5`,
//! `snubDodecahedron` with zero extra factors, `rational`), `actual`, `dimension 3|4`,
//! `scale s` or `scale vector …`, `offset …` (added after scaling, as vZome's Edit › Copy writes
//! it), numbers with fractions such as `(8/2,4/2)` or `(1/2,3)`. The W coordinate is dropped.
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
    bool moved = false; //!< vertices were off the lattice (a fractional offset): moved by vertex 0
};

struct VefWriteOptions
{
    bool faces = true; //!< write the model's faces (vZome shows them as panels)
};

ZomeModel read_vef(std::string_view text, VefReadInfo* info = nullptr);
ZomeModel read_vef_file(const std::string& path, VefReadInfo* info = nullptr);

//! Writes VEF 6 at vZome's raw scale, every node as a ball, faces if the model has them and
//! `options.faces` (else an empty face list: vZome then shows balls and struts only).
std::string write_vef(const ZomeModel& model, const VefWriteOptions& options = {});

} // namespace zomeify
