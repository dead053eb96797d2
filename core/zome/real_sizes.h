#pragma once
//! \file real_sizes.h
//! Physical sizes of the real Zometool parts (vZome's constants, design.md §2).

#include "core/zome/qphi.h"

namespace zomeify {

//! One raw vZome unit in millimetres.
inline constexpr double kMmPerVzomeUnit = 8.8365;
//! vZome's raw scale is 2φ² raw units per b0.
inline constexpr double kVzomeUnitsPerB0 = 2.0 * (kPhi + 1.0);
//! Millimetres per b0 (node centre to node centre of a B0 strut): 46.27 mm.
inline constexpr double kMmPerB0 = kMmPerVzomeUnit * kVzomeUnitsPerB0;
//! A ball measured across its blue faces.
inline constexpr double kBallDiameterMm = 17.673;
//! Part code of the white ball.
inline constexpr const char* kBallPartCode = "PZB-BAL-W";

} // namespace zomeify
