#pragma once
//! \file share_link_faces.h
//! The faces of a share link, in the node numbering of the link (share_link.h), either
//! explicit (version 1's layout) or as the exceptions to the rotation the struts suggest
//! (version 2): a closed Zome surface is its rotation system (strut_rotation.h), and the
//! geometric guess is right at most nodes, so only the others are stored.

#include <array>
#include <cstdint>
#include <vector>

#include "core/io/byte_codec.h"
#include "core/zome/zvec.h"

namespace zomeify {

using FaceList = std::vector<std::vector<uint32_t>>;
using StrutList = std::vector<std::array<uint32_t, 2>>;

//! Explicit faces: count, then per face its corner count − 3, its first corner as a zigzag
//! delta from the previous face's, and each further corner as the index of the next node among
//! the current node's neighbours sorted by index. Throws InvalidInputError if a face edge is
//! no strut.
void write_explicit_faces(ByteWriter& w, size_t node_count, const StrutList& struts, const FaceList& faces);
FaceList read_explicit_faces(ByteReader& r, size_t node_count, const StrutList& struts);

//! Rotation exceptions: count, then per node whose rotation is not the guessed one (in
//! increasing order) the gap from the previous such node and the rotation as a permutation of
//! the guess (Lehmer code, mixed radix, one varint; a digit per varint past 20 neighbours).
//! Returns false, writing nothing, when the faces are not a closed surface over the struts that
//! its rotation gives back exactly: the caller then writes explicit faces.
bool write_face_exceptions(ByteWriter& w, const std::vector<ZVec>& nodes, const StrutList& struts,
                           const FaceList& faces);
//! The faces back; InvalidInputError on a bad exception or a face longer than the model allows.
FaceList read_face_exceptions(ByteReader& r, const std::vector<ZVec>& nodes, const StrutList& struts);

} // namespace zomeify
