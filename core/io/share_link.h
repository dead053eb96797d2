#pragma once
//! \file share_link.h
//! Share links (design.md §4): the whole model in the URL fragment, `m=1.<base64url(binary)>`,
//! never sent to a server.
//!
//! The binary form needs no general-purpose compressor: every strut is a Zome vector, so a
//! traversal from a root node spells each strut as one byte (its vector id 0..185) and finds its
//! far node by exact position. Layout (version 1), all integers LEB128 varints:
//!   flags (bit 0: transform, bit 1: faces), node count, strut count,
//!   for each node in discovery order: [root position, 6 zigzag varints, when a new component
//!   starts] number of struts it introduces, then their vector ids (one byte each);
//!   faces (if flagged): count, then per face the corner count − 3, the first corner as a
//!   zigzag delta from the previous face's first corner, and for each further corner the index
//!   of the next node among the current node's neighbours sorted by index;
//!   transform (if flagged): scale and translation as four little-endian doubles.
//! Nodes are numbered in discovery order, so a round trip keeps the model up to the order of
//! its nodes, struts and faces' starting corners (which carry no meaning).

#include <string>
#include <string_view>

#include "core/zome/model.h"

namespace zomeify {

inline constexpr int kShareLinkVersion = 1;
//! Links longer than this are refused before decoding (16 MiB).
inline constexpr size_t kMaxShareLinkChars = size_t{16} << 20;

//! The fragment text `m=1.…` (without '#'). Throws InvalidInputError if a face edge is no strut.
std::string encode_share_link(const ZomeModel& model);

//! Accepts a full URL, `#m=…`, `m=…`, or the fragment among other `&`-separated parameters.
//! Hostile input is expected: every size is bounded, every index and strut checked, and any
//! problem is an InvalidInputError with a one-line message.
ZomeModel decode_share_link(std::string_view link);

} // namespace zomeify
