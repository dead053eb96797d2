#pragma once
//! \file model.h
//! ZomeModel: the plain interchange form of a Zome model (what files, links and the parts list
//! see). The annealer works on a halfedge mesh and converts to and from this.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/zome/zvec.h"

namespace zomeify {

//! Zome units (b0 = 1) → input mesh units: p_mesh = scale · p_zome + translation.
struct ModelTransform
{
    double scale = 1.0;
    std::array<double, 3> translation{0.0, 0.0, 0.0};
    friend bool operator==(const ModelTransform&, const ModelTransform&) = default;
};

struct ZomeModel
{
    std::vector<ZVec> nodes;                     //!< exact ball centres
    std::vector<std::array<uint32_t, 2>> struts; //!< node index pairs
    std::vector<std::vector<uint32_t>> faces;    //!< optional; counter-clockwise from outside
    ModelTransform transform;
    std::string stats_json = "{}"; //!< free-form run statistics (a JSON object)

    friend bool operator==(const ZomeModel&, const ZomeModel&) = default;
};

} // namespace zomeify
