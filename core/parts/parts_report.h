#pragma once
//! \file parts_report.h
//! The parts list with its kit plan, as the CLI prints it and the page shows it: one place so
//! both say the same. `owned` (may be empty) lists kits the user has; the report then adds the
//! loose parts still missing.

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/parts/kits.h"

namespace zomeify {

using OwnedKits = std::vector<std::pair<const Kit*, size_t>>;

//! Parses "creator3", "2xbasic", "creator 1, 2 x basic" into kits and counts.
OwnedKits parse_owned_kits(const std::string& text);

std::string parts_report_text(const PartsList& parts, const OwnedKits& owned);
std::string parts_report_json(const PartsList& parts, const OwnedKits& owned);
//! Counts by strut kind name plus "balls", as the JSON report writes them.
nlohmann::json part_counts_json(const PartCounts& c);

} // namespace zomeify
