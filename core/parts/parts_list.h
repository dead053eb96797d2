#pragma once
//! \file parts_list.h
//! The bill of materials of a Zome model: balls, struts per kind (colour, real length, part
//! code), totals, and the physical size of the built model.

#include <array>
#include <cstddef>
#include <string>

#include "core/zome/model.h"
#include "core/zome/slots.h"

namespace zomeify {

struct PartsList
{
    size_t balls = 0;
    std::array<size_t, kStrutKindCount> struts{}; //!< count per StrutKind (B0..R2)
    size_t strut_count = 0;
    double total_length_b0 = 0; //!< sum of strut lengths, b0 = 1
    double total_length_mm = 0; //!< the same in millimetres, node centre to node centre
    //! Extent of the built model (ball centres plus one ball diameter), x/y/z in cm.
    std::array<double, 3> size_cm{};
};

//! Counts the parts; throws InvalidInputError if a strut is not a Zome vector.
PartsList parts_list(const ZomeModel& model);

//! A readable table (the CLI's default output).
std::string parts_table(const PartsList& parts);
//! CSV: one row per part (balls first), header `part_code,kind,color,length_mm,count`.
std::string parts_csv(const PartsList& parts);
//! JSON object: {"balls":N,"struts":{"B0":n,...},"strut_count":..,"kinds":[...],"totals":...}.
std::string parts_json(const PartsList& parts);

} // namespace zomeify
