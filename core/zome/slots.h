#pragma once
//! \file slots.h
//! The Zometool system: 62 slots (ball holes: 30 blue, 20 yellow, 12 red), three strut sizes per
//! colour, so 186 Zome vectors, and the nine strut kinds B0..R2 (design.md §2, vZome's handedness).
//! Vector ids are slot·3 + size. Slots 2k and 2k+1 point in opposite directions.

#include <array>
#include <cstdint>
#include <string_view>

#include "core/zome/zvec.h"

namespace zomeify {

enum class Color : uint8_t
{
    Blue,
    Yellow,
    Red
};

enum class StrutKind : uint8_t
{
    B0,
    B1,
    B2,
    Y0,
    Y1,
    Y2,
    R0,
    R1,
    R2
};

inline constexpr int kSlotCount = 62;
inline constexpr int kSizeCount = 3;
inline constexpr int kVectorCount = kSlotCount * kSizeCount;
inline constexpr int kStrutKindCount = 9;
inline constexpr int kBlueSlots = 30, kYellowSlots = 20, kRedSlots = 12;

//! Slot ranges: blue [0, 30), yellow [30, 50), red [50, 62).
inline constexpr Color slot_color(int slot)
{
    return slot < kBlueSlots ? Color::Blue : slot < kBlueSlots + kYellowSlots ? Color::Yellow : Color::Red;
}
inline constexpr int opposite_slot(int slot) { return slot ^ 1; }
inline constexpr int vector_id(int slot, int size) { return slot * kSizeCount + size; }
inline constexpr int vector_slot(int id) { return id / kSizeCount; }
inline constexpr int vector_size(int id) { return id % kSizeCount; }
inline constexpr StrutKind strut_kind(Color color, int size)
{
    return static_cast<StrutKind>(static_cast<int>(color) * kSizeCount + size);
}
inline constexpr StrutKind vector_kind(int id) { return strut_kind(slot_color(vector_slot(id)), vector_size(id)); }
inline constexpr Color kind_color(StrutKind k) { return static_cast<Color>(static_cast<int>(k) / kSizeCount); }
inline constexpr int kind_size(StrutKind k) { return static_cast<int>(k) % kSizeCount; }

//! Static facts about one strut kind.
struct StrutKindInfo
{
    StrutKind kind;
    std::string_view name;      //!< "B0" .. "R2"
    std::string_view color;     //!< "blue", "yellow", "red"
    std::string_view part_code; //!< e.g. "PST-B1-BLU"
    QPhi length4;               //!< 4·length², exact (b0 = 1)
    double length;              //!< length in b0 units
    double length_mm;           //!< node centre to node centre, mm
};

const StrutKindInfo& kind_info(StrutKind k);
std::string_view color_name(Color c);

// noexcept: these are on the annealer's hot path, and under Emscripten's JS exceptions every call
// to a function that may throw, from a noexcept caller, goes through a JS trampoline.

//! The Zome vector with id 0..185 (slot·3 + size).
const ZVec& zome_vector(int id) noexcept;
//! All 186 Zome vectors in id order.
const std::array<ZVec, kVectorCount>& zome_vectors() noexcept;

//! The vector id of v, or -1 if v is not a Zome vector (exact, O(1)).
int vector_id_of(const ZVec& v) noexcept;
//! The slot of v (0..61), or -1 if v is not a Zome vector.
inline int slot_of(const ZVec& v) noexcept
{
    const int id = vector_id_of(v);
    return id < 0 ? -1 : vector_slot(id);
}

} // namespace zomeify
