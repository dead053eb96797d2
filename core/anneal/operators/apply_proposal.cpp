// apply_proposal(): executes a LocalChange with the mesh's primitives (paper §5.1: add/remove
// vertex, add/remove face). Removing a face removes the struts left without faces, so the
// removed struts go with the removed faces. A removed node is reused for an added one when there
// is one (MOVNODE keeps its handle and index; fewer dead elements to collect).
#include <algorithm>
#include <array>

#include "core/anneal/proposal.h"
#include "core/mesh/topology_error.h"

namespace zomeify {

void apply_proposal(ZomeMesh& mesh, const Proposal& proposal, FixedList<Face, LocalChange::kMaxFaces>* added_faces)
{
    const LocalChange& c = proposal.change;
    if (proposal.rejection != Rejection::None || c.overflowed())
        throw TopologyError("apply_proposal: the proposal was not valid");
    // Check before touching anything, so a broken contract leaves the mesh as it was.
    if (!new_positions_free(mesh, proposal))
        throw TopologyError("apply_proposal: a new node's position is occupied");
    for (Face f : c.removed_faces())
        if (!mesh.is_valid(f))
            throw TopologyError("apply_proposal: a removed face is not live");

    for (Face f : c.removed_faces())
        mesh.remove_face(f);
    for (Edge e : c.removed_struts())
        if (mesh.is_valid(e))
            throw TopologyError("apply_proposal: a removed strut kept a face");
    const auto& added = c.added_nodes();
    for (size_t i = 0; i < c.removed_nodes().size(); ++i)
    {
        const Vertex v = c.removed_nodes()[i];
        if (!mesh.is_isolated(v))
            throw TopologyError("apply_proposal: a removed node kept a strut");
        if (i < added.size())
            mesh.move_vertex(v, added[i]);
        else
            mesh.remove_vertex(v);
    }
    for (size_t i = c.removed_nodes().size(); i < added.size(); ++i)
        mesh.add_vertex(added[i]);
    for (const NewFace& f : c.added_faces())
    {
        std::array<Vertex, 4> corners;
        for (size_t j = 0; j < f.size; ++j)
        {
            corners[j] = mesh.find_vertex(f.corners[j]);
            if (!corners[j].is_valid())
                throw TopologyError("apply_proposal: a face corner is not a node");
        }
        const Face face = mesh.add_face(std::span<const Vertex>(corners.data(), f.size));
        if (added_faces)
            added_faces->push_back(face);
    }
}

} // namespace zomeify
