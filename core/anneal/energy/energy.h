#pragma once
//! \file energy.h
//! The annealer's energy (paper §4 with design.md §3.3's corrections), evaluated over a whole mesh:
//!   E = w_d·E_dist + w_o·E_orient + w_f·E_fair + w_c·E_complex,
//! with every term an average over its samples (see EnergyTerms for the formulas). Distances are in
//! b0 units: a sample p (node, strut midpoint, face barycentre) is mapped to S's units by the model
//! transform, projected, and its distance divided by the transform's scale.
//!
//! The orientation terms:
//!  - tangential, per strut a–b with d = b − a and m = (a + b)/2:  (dᵀ n(π(m)))² / ‖d‖²  (paper §4.2);
//!  - normal, per corner b of a face whose corners a, b, c run counter-clockwise seen from outside:
//!    (1 − n(π(b))ᵀ n_b)² / 4 with the unit outward corner normal
//!    n_b = (c − b) × (a − b) / ‖(c − b) × (a − b)‖ (design §3.3; the paper prints an inward,
//!    unnormalised normal). A straight corner counts n_b ⟂ n(π(b)).
//! Both parts lie in [0, 1]; E_orient = 0.25·tangential + 0.75·normal.
//!
//! For local changes, see energy_state.h (same sample values, incremental sums).

#include "core/anneal/energy/energy_options.h"
#include "core/anneal/energy/energy_sums.h"
#include "core/anneal/energy/surface_context.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

//! All terms of E for the live elements of `mesh` against the surface of `context`. Throws
//! InvalidInputError if options.w_complexity ≠ 0 and options.target_nodes = 0. Thread-safe
//! (reads the mesh; the context's cache is concurrent).
EnergyTerms evaluate_energy(const ZomeMesh& mesh, const SurfaceContext& context, const EnergyOptions& options);

//! The sums of every term but E_surface (surface and surface_samples are 0).
EnergySums evaluate_local_sums(const ZomeMesh& mesh, const SurfaceContext& context, const EnergyOptions& options);

} // namespace zomeify
