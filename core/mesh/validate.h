#pragma once
//! \file validate.h
//! validate(): the full consistency check of a ZomeMesh (style.md §7 rule 5), run by tests after
//! every edit and by the pipeline on each extracted or exported model. It checks connectivity
//! (next/prev/opposite/face/vertex links), closedness, 2-manifoldness (one fan per vertex), the
//! Euler characteristic and genus of every component, and the Zome rules of design.md §3.4: every
//! edge a Zome vector with its stored id correct, unique node positions (and the position index in
//! sync), no two struts in one slot of a node, no doubly connected node pair, faces with 3 or 4
//! corners, and a minimum valence. O(V + E + F) time; allocates its own work arrays.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh/surface_mesh.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

//! What validate() requires (the defaults are the annealer's invariants).
struct ValidateOptions
{
    bool require_closed = true; //!< no boundary halfedges
    bool tri_quad_only = true;  //!< faces have 3 or 4 corners (otherwise any polygon)
    bool check_zome = true;     //!< Zome vectors, stored ids, positions, slots (ZomeMesh only)
    size_t min_valence = 3;     //!< every node has at least this many struts
    size_t max_messages = 20;   //!< detailed messages kept in the report
};

//! The kinds of problem validate() reports.
enum class MeshProblem : uint8_t
{
    Connectivity,      //!< broken next/prev/opposite/face/vertex links or deleted references
    Boundary,          //!< a boundary halfedge in a mesh required to be closed
    NonManifoldVertex, //!< a vertex whose faces do not form one fan (or one half-disc)
    NonZomeEdge,       //!< an edge whose vector is not one of the 186 Zome vectors
    WrongVectorId,     //!< a stored per-halfedge vector id (slot) that does not match the positions
    DuplicatePosition, //!< two nodes at one exact position
    PositionIndex,     //!< the position index disagrees with the positions
    SlotConflict,      //!< two struts of one node in the same slot
    DoubleEdge,        //!< two edges between the same two nodes
    FaceSize,          //!< a face that is not a triangle or quad (when required)
    LowValence         //!< a node with fewer struts than required (isolated nodes included)
};
inline constexpr size_t kMeshProblemCount = 11;

//! A short name for a problem kind ("non-manifold vertex").
const char* to_string(MeshProblem p);

//! One connected component (isolated vertices are not components; they count as LowValence).
struct MeshComponent
{
    size_t vertices = 0;
    size_t edges = 0;
    size_t faces = 0;
    size_t boundary_loops = 0;
    long euler_characteristic = 0; //!< V − E + F
    int genus = 0;                 //!< (2 − χ − boundary loops) / 2
};

//! The result of validate(): counts per problem kind, the first messages and the topology.
struct ValidationReport
{
    std::array<size_t, kMeshProblemCount> problem_counts{};
    std::vector<std::string> messages; //!< first problems in detail ("vertex v3: ...")
    size_t n_vertices = 0, n_edges = 0, n_faces = 0;
    size_t boundary_loops = 0;
    long euler_characteristic = 0;
    int genus = 0;                         //!< sum over components
    std::vector<MeshComponent> components; //!< filled only when connectivity is sound
    bool topology_known = false;           //!< false when broken links made traversal unsafe

    bool ok() const;
    size_t count(MeshProblem p) const { return problem_counts[static_cast<size_t>(p)]; }
    bool has(MeshProblem p) const { return count(p) != 0; }
    size_t total_problems() const;
    //! One line: "valid: 26 nodes, 48 struts, 24 faces, 1 component, genus 0", or the problem
    //! counts followed by the first detailed messages.
    std::string message() const;
};

//! Validates connectivity and topology of any polygon mesh (the Zome checks are skipped).
ValidationReport validate(const SurfaceMesh& mesh, const ValidateOptions& options = {});
//! Validates a Zome mesh: topology plus the Zome rules when options.check_zome.
ValidationReport validate(const ZomeMesh& mesh, const ValidateOptions& options = {});

} // namespace zomeify
