#pragma once
//! \file mirrored.h
//! Mirror-symmetric annealing (issue 41): every change is made together with its mirror image, so
//! a model that starts symmetric stays exactly symmetric. After propose() has filled a proposal,
//! mirror_proposal() either
//!  - keeps it as it is, when the change is its own mirror image (a node on the plane moving within
//!    it, a symmetric face split on the plane, ...), or
//!  - appends the mirror image of the change to it (claiming the mirrored nodes), when the two
//!    touch no common element and their new struts and faces fit together at the nodes they share,
//!  - and otherwise refuses it (Rejection::MirrorOverlap): a change crossing the plane that is not
//!    symmetric itself has no symmetric counterpart.
//! The energy then simulates the whole pair as one LocalChange, so ΔE stays exact.

#include "core/anneal/proposal.h"
#include "core/zome/lattice_mirror.h"

namespace zomeify {

//! Makes `proposal` (valid, from propose(), its nodes held by `claims`) symmetric under `mirror`
//! on a model that is symmetric. Returns Rejection::None when `proposal` now holds the symmetric
//! change, else why not (Busy: a mirrored node is held by another thread; Topology: the model
//! itself is not symmetric there, a broken precondition). noexcept and allocation-free.
Rejection mirror_proposal(const ZomeMesh& mesh, const LatticeMirror& mirror, Claims& claims,
                          Proposal& proposal) noexcept;

} // namespace zomeify
