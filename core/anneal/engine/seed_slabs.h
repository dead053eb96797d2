#pragma once
//! \file seed_slabs.h
//! Where each annealing thread draws its seeds (internal to core/anneal/engine).
//!
//! With several threads, every node a proposal claims is an atomic write, and every commit writes
//! the mesh around it. When all threads roam the whole model, those cache lines bounce between
//! cores all the time and two threads run little faster than one. So each thread draws its seeds
//! from its own slab of the model: the nodes between two quantiles along a direction. Slabs change
//! with the epoch (direction, and which thread has which slab), so over a run every thread visits
//! the whole model and the sampling stays uniform on average. Slabs only steer the seeds: claims
//! still guard every node, so a proposal at a slab's edge may reach into the next one.

#include <cstdint>
#include <vector>

#include "core/mesh/zome_mesh.h"

namespace zomeify {

//! Proposals (over all threads) per slab epoch.
inline constexpr uint64_t kSlabEpochProposals = 65536;

//! The live nodes of thread `index`'s slab (of `threads`) in `epoch`. Reads every node's position:
//! call it under the commit lock. Empty when the mesh has no live node.
std::vector<MeshIndex> seed_slab(const ZomeMesh& mesh, uint64_t epoch, int index, int threads);

} // namespace zomeify
