#pragma once
//! \file proposal.h
//! The contract between the seven operators (paper §3.2, §5.1; design.md §3.4) and the annealing
//! engine (design.md §3.5–§3.6). One annealing step on one thread:
//!
//!   1. the engine picks a random live node `seed`, claims it, and a random operator kind;
//!   2. propose(kind, mesh, seed, rng, claims, out) picks the operator's element near the seed
//!      (the node itself, one of its struts, or one of its faces), claims every node it reads and
//!      every node simulate() will read, checks the operator's validity rules and fills `out`;
//!      false (with a reason) when the proposal is not valid or a claim failed;
//!   3. the engine simulates the energy change of out.change (EnergyState::simulate), decides
//!      (Metropolis), and on acceptance, inside its commit critical section, calls
//!      apply_proposal(mesh, out) and EnergyState::commit;
//!   4. the engine releases the claims.
//!
//! Claiming rule (what makes step 2 lock-free and race-free): a node must be claimed before its
//! position, its star or anything incident to it is read. propose() must claim at least the
//! nodes of the support region and its link, and every neighbour of a node whose 1-ring changes
//! (E_fair reads those positions). apply_proposal() only changes elements all of whose nodes
//! are claimed.

#include <cstdint>
#include <string_view>

#include "core/anneal/energy/local_change.h"
#include "core/anneal/node_claims.h"
#include "core/anneal/random.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

enum class OperatorKind : uint8_t
{
    InsNode,    //!< INSNODE(f): a new node inside face f, connected to every reachable link node
    AddDiag,    //!< ADDDIAG(f): a new diagonal strut splitting quad f into two triangles
    SplitStrut, //!< SPLITSTRUT(s): a new node splitting strut s (connected at least to its ends)
    RemDiag,    //!< REMDIAG(s): removes strut s, merging its two triangles into a quad
    FlipDiag,   //!< FLIPDIAG(s): replaces the diagonal s of two triangles by the other diagonal
    MovNode,    //!< MOVNODE(n): moves node n, reconnecting it to every reachable link node
    RemNode,    //!< REMNODE(n): removes node n and fills its link with triangles/quads
};
inline constexpr int kOperatorKinds = 7;

//! "INSNODE", "ADDDIAG", ... (the paper's names).
std::string_view operator_name(OperatorKind kind) noexcept;

//! Why a proposal was not produced (for statistics; the engine counts them per kind).
enum class Rejection : uint8_t
{
    None,         //!< a valid proposal was produced
    Busy,         //!< a node was claimed by another thread
    NoCandidate,  //!< no element of that kind near the seed, or no new position found
    FaceSize,     //!< a face would have fewer than 3 or more than 4 corners
    Valence,      //!< a node would have valence < 3
    Occupied,     //!< a new position is already a node
    SlotConflict, //!< two struts in one slot of a node
    DoubleStrut,  //!< a node pair would be joined twice
    LinkTwice,    //!< a link node pointed to twice (non-disc neighbourhood)
    Topology,     //!< any other manifold/genus safeguard
    Overflow,     //!< the change did not fit LocalChange's fixed capacity
    FoldedQuad,   //!< a quad whose diagonal is also a strut (two faces folded onto each other)
    FoldOver,     //!< (from the energy's simulate) a new face facing against the surface
    Uncovered,    //!< (at commit, after Metropolis) would leave a part of S with no node near (coverage_guard.h)
    // At commit, after Metropolis: parts that could not be built side by side (clearance_index.h).
    BallsTooClose,    //!< two balls
    BallOnStrut,      //!< a ball and a strut it does not hold
    StrutsTooClose,   //!< two struts sharing no ball (a bow-tie quad among them)
    StrutThroughFace, //!< a strut through a face it shares no ball with
    OverKits,         //!< (at commit) a part count over the run's limits (part_tally.h)
    OutsideRegion,    //!< (at commit) a change outside the region the run may change (change_region.h)
    MirrorOverlap     //!< a change across the mirror plane that is not its own mirror image (mirrored.h)
};
inline constexpr int kRejectionKinds = 21;
std::string_view rejection_name(Rejection r) noexcept;

struct Proposal
{
    OperatorKind kind = OperatorKind::InsNode;
    Rejection rejection = Rejection::None;
    //! The whole edit: removed elements (handles) and new elements (positions, faces CCW from
    //! outside). The energy simulates it; apply_proposal() executes it.
    LocalChange change;
};

//! Fills `out` with a random valid proposal of `kind` around `seed` (a live node that `claims`
//! already holds). Returns false, with out.rejection set, if none. Reads only claimed nodes; never
//! modifies the mesh; noexcept and allocation-free in steady state (thread_local scratch is fine).
bool propose(OperatorKind kind, const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Proposal& out) noexcept;

//! Executes a proposal produced by propose() on the unchanged mesh (same claims held): removes
//! its faces, struts and nodes, adds its nodes, and adds its faces (creating their struts). The
//! mesh must have capacity reserved for the additions (SurfaceMesh::has_capacity_for) when other
//! threads read it concurrently. Throws TopologyError only on a broken contract (a bug). With
//! `added_faces`, the new faces' handles are appended there in the order of change.added_faces().
void apply_proposal(ZomeMesh& mesh, const Proposal& proposal,
                    FixedList<Face, LocalChange::kMaxFaces>* added_faces = nullptr);

//! Whether every node the proposal adds still has a free position (a removed node's own position
//! counts as free). propose() checks this against the global position index, but another thread
//! may commit a node at the same position before this proposal commits (two claimed regions can
//! be far apart in the mesh and close in space): call it inside the commit critical section,
//! right before apply_proposal(), and drop the proposal if it is false.
bool new_positions_free(const ZomeMesh& mesh, const Proposal& proposal) noexcept;

} // namespace zomeify
