#pragma once
//! \file share_link.h
//! Share links (design.md §4): the whole model in the URL fragment, `m=2.<base64url(binary)>`,
//! never sent to a server. Links of version 1 still decode.
//!
//! The binary form needs no general-purpose compressor: every strut is a Zome vector, so a
//! traversal from a root node per component spells each strut as one byte (its vector id
//! 0..185) and finds its far node by exact position. All integers are LEB128 varints.
//!
//! Version 2: flags (bit 0: transform, bit 1: explicit faces, bit 2: faces from the struts),
//! node count, strut count, component count and each component's root position (6 zigzag
//! varints); then for each node in discovery order the number of struts it introduces as a
//! nibble (two per byte, low first; 15 means 15 + a varint from the list after the nibbles);
//! the vector ids of all struts, each node's sorted by id; the faces (share_link_faces.h): as
//! the exceptions to the rotation the struts suggest, or explicitly when the faces are not a
//! closed surface over the struts; the transform as four little-endian doubles.
//!
//! Version 1: flags (bit 0: transform, bit 1: faces), node count, strut count, then per node a
//! root position when a component starts, its strut count and vector ids, explicit faces, the
//! transform.
//!
//! Nodes are numbered in discovery order, so a round trip keeps the model up to the order of
//! its nodes, struts and faces, and faces' starting corners (which carry no meaning).

#include <string>
#include <string_view>

#include "core/zome/model.h"

namespace zomeify {

inline constexpr int kShareLinkVersion = 2;
//! Links longer than this are refused before decoding (16 MiB).
inline constexpr size_t kMaxShareLinkChars = size_t{16} << 20;

//! The fragment text `m=1.…` (without '#'). Throws InvalidInputError if a face edge is no strut.
std::string encode_share_link(const ZomeModel& model);

//! Accepts a full URL, `#m=…`, `m=…`, or the fragment among other `&`-separated parameters.
//! Hostile input is expected: every size is bounded, every index and strut checked, and any
//! problem is an InvalidInputError with a one-line message.
ZomeModel decode_share_link(std::string_view link);

} // namespace zomeify
