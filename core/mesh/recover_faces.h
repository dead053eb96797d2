#pragma once
//! \file recover_faces.h
//! Recovers the faces of a Zome model given only as balls and struts (vZome files such as the
//! paper's bunny.vef carry no faces; design.md §6). With an outward normal per node, the struts
//! around each node are ordered counter-clockwise in its tangent plane; that rotation system
//! defines a closed oriented surface whose faces are traced dart by dart. The result is accepted
//! only if every face is a triangle or a quad without repeated nodes.

#include <array>
#include <string>
#include <vector>

#include "core/zome/model.h"

namespace zomeify {

struct FaceRecovery
{
    bool ok = false;
    std::string error; //!< what is wrong when !ok (counts of bad faces, nodes without struts, ...)
    std::vector<std::vector<uint32_t>> faces; //!< counter-clockwise seen from outside
};

//! `normals[i]` is an outward direction at node i (any length > 0), e.g. the input surface's
//! normal at π(node). Ignores model.faces.
FaceRecovery recover_faces(const ZomeModel& model, const std::vector<std::array<double, 3>>& normals);

//! The faces of a rotation system: `rotation[v]` lists v's neighbours counter-clockwise seen
//! from outside (every strut must appear at both ends). Every dart is used once; a face is
//! traced from each unused dart in order of node, then position. Faces may have any length
//! (a bad rotation gives long ones): callers check.
std::vector<std::vector<uint32_t>> trace_faces(const std::vector<std::vector<uint32_t>>& rotation);

//! Normals pointing away from the centroid of the nodes: good enough for star-shaped models.
std::vector<std::array<double, 3>> centroid_normals(const ZomeModel& model);

} // namespace zomeify
