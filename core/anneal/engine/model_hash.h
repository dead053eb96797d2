#pragma once
//! \file model_hash.h
//! A 64-bit hash of a Zome model that ignores numbering: the sorted node positions, the sorted
//! struts (as position pairs) and the sorted faces (as position cycles from their smallest corner)
//! and the transform. Equal models give equal hashes on every platform; the determinism tests
//! compare it with a golden constant.

#include <cstdint>

#include "core/zome/model.h"

namespace zomeify {

uint64_t canonical_model_hash(const ZomeModel& model);

} // namespace zomeify
