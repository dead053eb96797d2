#pragma once
//! \file mirror_halves.h
//! The parts of a mirror-symmetric model by where they go (issue 41, item 3): one half (built twice,
//! the second time mirrored: the same parts) and the middle (balls on the plane and the struts that
//! lie in it or cross it). A strut from a ball of a half to a ball on the plane belongs to the half.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/parts/kits.h"
#include "core/zome/lattice_mirror.h"
#include "core/zome/model.h"

namespace zomeify {

struct MirrorHalves
{
    LatticeMirror mirror;
    PartCounts half{};   //!< one half (index 0..8 strut kinds B0..R2, 9 balls)
    PartCounts middle{}; //!< on the plane or across it
};

//! The split of a model that maps exactly onto itself about a plane across an axis
//! (lattice_mirror.h, model_mirror); nothing for any other model.
std::optional<MirrorHalves> mirror_halves(const ZomeModel& model);

//! "mirror-symmetric (about a plane across the x axis): each half 160 balls, 380 struts (…); the
//! middle 40 balls, 52 struts (…)".
std::string mirror_halves_text(const MirrorHalves& halves);
nlohmann::json mirror_halves_json(const MirrorHalves& halves);

} // namespace zomeify
