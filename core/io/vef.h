#pragma once
//! \file vef.h
//! vZome's exact VEF format (design.md §4). Tokens are separated by whitespace; `(a,b)` means
//! a·φ + b. Layout: `vZome VEF <version> field golden`, vertex count, W X Y Z per vertex, edge
//! count and pairs, face count and `k i1 … ik` rows, ball count and vertex indices.
//!
//! As vZome reads it (its VefParser): the header `vZome VEF <version>` may be missing, the edge,
//! face and ball sections are each optional, and text after the last one is ignored. The ball list
//! says which vertices carry a ball (before version 6, which has none, every vertex does): a vertex
//! with neither a ball nor a strut is no part and is dropped, and a strut end without a ball is
//! kept as a ball and noted (a builder needs one there). A file with no strut and no ball is a
//! shape (vZome's part shapes), not a model, and is refused as such; so are green struts, fields
//! other than the golden one, 4D models, and numbers too large, each with that reason.
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
#include <vector>

#include "core/zome/model.h"

namespace zomeify {

struct VefReadInfo
{
    int phi_power = 2;              //!< the file's scale is 2φ^phi_power raw units per b0
    int version = 0;                //!< the VEF version number in the header (0: none, as vZome allows)
    size_t balls = 0;               //!< vertices the file gives a ball
    bool moved = false;             //!< vertices were off the lattice (a fractional offset): moved by vertex 0
    size_t ends_without_ball = 0;   //!< strut ends the file gives no ball (a builder needs one there)
    size_t vertices_dropped = 0;    //!< vertices with neither a ball nor a strut (not parts)
    bool scale_set_aside = false;   //!< the file's uniform scale made no strut a Zome strut: read without it
    std::vector<std::string> notes; //!< one sentence per point a person should know, for the loaders to show
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
