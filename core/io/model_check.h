#pragma once
//! \file model_check.h
//! Validation of a ZomeModel read from an untrusted source (file, share link): every index in
//! range, every strut a Zome vector, no two nodes at one position, no strut twice, no two struts
//! in one slot of a ball. Throws InvalidInputError naming the first problem.

#include "core/zome/model.h"

namespace zomeify {

//! Upper bounds that keep hostile input from exhausting memory or time.
inline constexpr size_t kMaxModelNodes = 2'000'000;
inline constexpr size_t kMaxModelStruts = 8'000'000;
inline constexpr size_t kMaxModelFaces = 8'000'000;
inline constexpr size_t kMaxFaceSize = 64;

void check_model(const ZomeModel& model);

} // namespace zomeify
