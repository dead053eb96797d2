#pragma once
//! \file kits.h
//! Standard Zometool kits (design.md §2, kept as data) and the kit plan of a parts list:
//! - plan_kits: the combination of kits with the fewest parts bought that covers the model
//!   (ties: fewer kits), with what is left over;
//! - missing_parts: with kits the user already has, the loose parts still missing.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/parts/parts_list.h"

namespace zomeify {

struct Kit
{
    std::string_view id;   //!< "basic", "creator1", "creator3", "workshop"
    std::string_view name; //!< "Creator 1"
    //! Struts of each length per colour (blue, yellow, red): a kit has that many of each size.
    std::array<size_t, 3> struts_per_length;
    size_t balls;
    size_t part_count() const
    {
        return 3 * (struts_per_length[0] + struts_per_length[1] + struts_per_length[2]) + balls;
    }
};

const std::vector<Kit>& standard_kits();
//! The kit with this id or name (case-insensitive, spaces ignored); InvalidInputError if none.
const Kit& find_kit(std::string_view id_or_name);

//! Parts per kind: index 0..8 the strut kinds B0..R2, index 9 the balls.
using PartCounts = std::array<size_t, kStrutKindCount + 1>;
PartCounts part_counts(const PartsList& parts);
PartCounts kit_contents(const std::vector<std::pair<const Kit*, size_t>>& kits);

struct KitPlan
{
    std::vector<std::pair<const Kit*, size_t>> kits; //!< kit and how many, largest kits first
    size_t parts_bought = 0;
    PartCounts spare{}; //!< parts left over after building
};

KitPlan plan_kits(const PartsList& parts);
//! Loose parts still needed when building with `owned` kits (zero where the kits suffice).
PartCounts missing_parts(const PartsList& parts, const std::vector<std::pair<const Kit*, size_t>>& owned);

//! Readable text and JSON of a plan (and of what is missing with owned kits, if given).
std::string kit_plan_text(const KitPlan& plan);
//! "4 Creator 3 + 1 Creator 1" ("" for none).
std::string kits_text(const std::vector<std::pair<const Kit*, size_t>>& kits);
std::string part_counts_text(const PartCounts& counts);

} // namespace zomeify
