#pragma once
//! \file clearance_rules.h
//! What it takes for two parts of a Zome model to be built side by side (design.md §3.8). Real
//! parts have a size: a ball is 17.673 mm across its blue faces and a strut about 6 mm thick, with
//! 1 b0 = 46.27 mm between ball centres. Distances here are in b0 units and measured between ball
//! centres and strut axes (centre to centre segments); each minimum is the parts' own size plus a
//! margin of about 1.4 mm, for the play of real parts and the builder's hands.
//!
//!  - two balls:                 centre distance            ≥ ball diameter + margin
//!  - a ball and a strut it does not hold: centre to axis  ≥ ball radius + strut radius + margin
//!  - two struts sharing no ball: axis to axis              ≥ strut thickness + margin
//!    (this also forbids a quad whose own opposite struts cross: a "bow tie")
//!  - a strut and a face sharing no ball: the strut must not pass through the face (two faces of a
//!    closed surface intersect exactly when a strut of one passes through the other).

#include "core/zome/real_sizes.h"

namespace zomeify {

//! Strut thickness in millimetres (the round shaft; the ends are thinner).
inline constexpr double kStrutThicknessMm = 6.0;
//! The play left between two parts, in millimetres.
inline constexpr double kClearanceMarginMm = 1.4;

inline constexpr double kBallDiameterB0 = kBallDiameterMm / kMmPerB0;       //!< 0.382
inline constexpr double kStrutThicknessB0 = kStrutThicknessMm / kMmPerB0;   //!< 0.130
inline constexpr double kClearanceMarginB0 = kClearanceMarginMm / kMmPerB0; //!< 0.030

//! Smallest allowed distance between two ball centres (b0): 0.412.
inline constexpr double kMinBallBall = kBallDiameterB0 + kClearanceMarginB0;
//! Smallest allowed distance from a ball centre to the axis of a strut it does not hold (b0): 0.286.
inline constexpr double kMinBallStrut = 0.5 * kBallDiameterB0 + 0.5 * kStrutThicknessB0 + kClearanceMarginB0;
//! Smallest allowed distance between the axes of two struts sharing no ball (b0): 0.160.
inline constexpr double kMinStrutStrut = kStrutThicknessB0 + kClearanceMarginB0;

} // namespace zomeify
