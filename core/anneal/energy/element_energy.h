#pragma once
//! \file element_energy.h
//! The energy contributions of single elements: a node, a strut, a face, given either as mesh
//! elements or as exact positions (for elements an operator is about to create). The full and the
//! incremental evaluation both go through these functions, so an element contributes the same
//! integers whichever way it is counted.

#include <span>

#include "core/anneal/energy/energy_samples.h"
#include "core/anneal/energy/node_normals.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

//! A strut's distance sample (at its midpoint) and tangential orientation value.
struct StrutEnergy
{
    EnergyFixed distance = 0;
    EnergyFixed tangential = 0;
};

//! A face's distance sample (at its barycentre) and the sum of its corners' normal values.
struct FaceEnergy
{
    EnergyFixed distance = 0;
    EnergyAccumulator normal = 0;
    int corners = 0;
    bool fold_over = false; //!< faces against the surface at its barycentre (is_fold_over)
};

//! Distance sample of a node at p.
EnergyFixed node_distance_energy(const ZVec& p, const SurfaceContext& context, const EnergyOptions& options) noexcept;

//! The strut a–b.
StrutEnergy strut_energy(const ZVec& a, const ZVec& b, const SurfaceContext& context,
                         const EnergyOptions& options) noexcept;

//! Normal value of corner `at` between `prev` and `next` (counter-clockwise seen from outside),
//! with n_at the surface normal at π(at).
EnergyFixed corner_energy(const ZVec& prev, const ZVec& at, const ZVec& next, const Vec3& n_at) noexcept;

//! The polygon with these corners, counter-clockwise seen from outside (at least 3); node normals
//! come from (and are remembered in) `normals`.
FaceEnergy face_energy(std::span<const ZVec> corners, NodeNormals& normals, const EnergyOptions& options) noexcept;
//! A face of the mesh (any number of corners).
FaceEnergy face_energy(const ZomeMesh& mesh, Face f, NodeNormals& normals, const EnergyOptions& options) noexcept;

//! face_energy(corners, …).fold_over alone: the face's Newell normal against the surface normal
//! at π(barycentre).
bool face_is_fold_over(std::span<const ZVec> corners, const SurfaceContext& context) noexcept;

//! Fairing value of a node at p whose 1-ring sums to ring_sum over ring_size nodes.
EnergyFixed fairing_energy(const ZVec& p, const LatticeSum& ring_sum, int ring_size) noexcept;
//! Fairing value of a mesh node with its current 1-ring.
EnergyFixed fairing_energy(const ZomeMesh& mesh, Vertex v) noexcept;

} // namespace zomeify
