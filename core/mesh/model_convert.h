#pragma once
//! \file model_convert.h
//! Conversion between the interchange ZomeModel (nodes, struts, faces) and the annealer's
//! ZomeMesh. from_model() is the gate for outside data (the extracted Z0, loaded files): it
//! rejects anything the mesh cannot represent, or that is not a valid Zome surface, with a
//! message naming the node, strut or face at fault.

#include "core/mesh/zome_mesh.h"
#include "core/zome/model.h"

namespace zomeify {

//! What from_model() accepts.
struct FromModelOptions
{
    bool require_closed = true; //!< reject surfaces with boundary edges
    bool require_zome = true;   //!< reject edges that are not Zome vectors
};

//! Builds the mesh of a model's faces (counter-clockwise from outside). Node i becomes vertex i.
//! Throws InvalidInputError if the model has no faces, two nodes share a position, a face is
//! degenerate, the faces are non-manifold or inconsistently oriented, a node lies on no face, a
//! strut is not a face edge (or a face edge is missing from a non-empty strut list), or, as
//! options require, the surface is open or an edge is not a Zome vector.
ZomeMesh from_model(const ZomeModel& model, const FromModelOptions& options = {});

//! The live part of a mesh as a model: nodes in vertex order (deleted ones skipped), one strut
//! per edge, faces starting at the from-vertex of their stored halfedge.
ZomeModel to_model(const ZomeMesh& mesh, const ModelTransform& transform = {});

} // namespace zomeify
