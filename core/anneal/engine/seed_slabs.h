#pragma once
//! \file seed_slabs.h
//! Where the annealing threads draw their seeds (internal to core/anneal/engine).
//!
//! The model is cut into slabs: the live nodes between two quantiles along a direction. For one
//! epoch, each thread draws its seeds from one slab; epoch after epoch the slabs sweep the model
//! (each thread moves to the next slab) and the cutting direction changes, so over a run every
//! node is a seed about equally often. Two reasons:
//! - Quality. Concentrated proposals settle a region before moving on. On the bunny (392 nodes, a
//!   budget of 2·10^7 proposals, one thread) the final energy was 2.0–2.3 with 2–8 slabs against
//!   3.0–3.6 with seeds drawn uniformly over the whole model (tests/bench/README.md).
//! - Speed with several threads. Every claim is an atomic write and every commit writes the mesh;
//!   threads in disjoint slabs keep those cache lines on their own core (2 threads went from 1.1x
//!   to 1.8x the proposals of one).
//! Slabs only steer the seeds: claims still guard every node, so a proposal at a slab's edge may
//! reach into the next one. The lists are computed from the mesh at the start of an epoch; nodes
//! added during an epoch become seeds in the next.

#include <cstdint>
#include <vector>

#include "core/mesh/zome_mesh.h"

namespace zomeify {

struct SlabPlan
{
    int slabs = 1;                //!< slabs the model is cut into
    uint64_t epoch_proposals = 0; //!< proposals (all threads together) per epoch
};

//! The plan for a model of `nodes` live nodes annealed by `threads` threads: max(4, threads)
//! slabs, and epochs long enough for about 125 proposals per node of the model per epoch (at
//! least 4096).
SlabPlan slab_plan(size_t nodes, int threads) noexcept;

//! The live nodes of slab `slab` (0 ≤ slab < slabs) in `epoch`'s cut. Reads every node's position:
//! with several threads call it under the commit lock. Empty when the slab has no node.
std::vector<MeshIndex> seed_slab(const ZomeMesh& mesh, uint64_t epoch, int slab, int slabs);

//! The slab thread `index` of `threads` works on in `epoch`: the threads are spread evenly over
//! the slabs, and all move one slab on per epoch.
int slab_of_thread(uint64_t epoch, int index, int threads, int slabs) noexcept;

} // namespace zomeify
