#include "core/mesh/model_convert.h"

#include <sstream>
#include <string>

#include "core/base/errors.h"
#include "core/mesh/topology_error.h"

namespace zomeify {

ZomeMesh from_model(const ZomeModel& model, const FromModelOptions& options)
{
    if (model.faces.empty())
        throw InvalidInputError("the Zome model has no faces; the annealer needs its surface (faces "
                                "counter-clockwise seen from outside)");
    ZomeMesh mesh;
    size_t n_corners = 0;
    for (const auto& f : model.faces)
        n_corners += f.size();
    mesh.reserve(model.nodes.size(), n_corners / 2 + 1, model.faces.size());
    for (size_t i = 0; i < model.nodes.size(); ++i)
    {
        const Vertex other = mesh.find_vertex(model.nodes[i]);
        if (other.is_valid())
        {
            std::ostringstream os;
            os << "nodes " << other.idx() << " and " << i << " share the position " << model.nodes[i];
            throw InvalidInputError(os.str());
        }
        mesh.add_vertex(model.nodes[i]);
    }
    try
    {
        mesh.build_faces(model.faces);
    }
    catch (const TopologyError& e)
    {
        throw InvalidInputError(std::string("the model's faces are not a valid surface: ") + e.what());
    }
    for (MeshIndex i = 0; i < mesh.vertices_size(); ++i)
        if (mesh.is_isolated(Vertex(i)))
            throw InvalidInputError("node " + std::to_string(i) + " lies on no face");
    for (MeshIndex i = 0; i < mesh.edges_size(); ++i)
    {
        const Edge e(i);
        const Halfedge h = SurfaceMesh::halfedge(e, 0);
        const std::string name =
            "edge " + std::to_string(mesh.from_vertex(h).idx()) + "-" + std::to_string(mesh.to_vertex(h).idx());
        if (options.require_closed && mesh.is_boundary(e))
            throw InvalidInputError("the surface is not closed: " + name + " has a face on one side only");
        if (options.require_zome && mesh.vector_id(h) == kNoZomeVector)
            throw InvalidInputError(name + " is not a Zome vector");
    }
    if (!model.struts.empty())
    {
        std::vector<uint8_t> matched(mesh.edges_size(), 0);
        for (size_t i = 0; i < model.struts.size(); ++i)
        {
            const auto [a, b] = model.struts[i];
            const std::string name =
                "strut " + std::to_string(i) + " (" + std::to_string(a) + "-" + std::to_string(b) + ")";
            if (a >= mesh.vertices_size() || b >= mesh.vertices_size())
                throw InvalidInputError(name + " uses a node out of range");
            const Edge e = mesh.find_edge(Vertex(a), Vertex(b));
            if (!e.is_valid())
                throw InvalidInputError(name + " is not an edge of any face");
            if (matched[e.idx()])
                throw InvalidInputError(name + " is listed twice");
            matched[e.idx()] = 1;
        }
        if (model.struts.size() != mesh.n_edges())
            throw InvalidInputError("the faces have " + std::to_string(mesh.n_edges()) + " edges but the model lists " +
                                    std::to_string(model.struts.size()) + " struts");
    }
    return mesh;
}

ZomeModel to_model(const ZomeMesh& mesh, const ModelTransform& transform)
{
    ZomeModel model;
    model.transform = transform;
    std::vector<uint32_t> index(mesh.vertices_size(), 0);
    model.nodes.reserve(mesh.n_vertices());
    for (MeshIndex i = 0; i < mesh.vertices_size(); ++i)
        if (!mesh.is_deleted(Vertex(i)))
        {
            index[i] = static_cast<uint32_t>(model.nodes.size());
            model.nodes.push_back(mesh.position(Vertex(i)));
        }
    model.struts.reserve(mesh.n_edges());
    for (MeshIndex i = 0; i < mesh.edges_size(); ++i)
    {
        const Edge e(i);
        if (!mesh.is_deleted(e))
            model.struts.push_back({index[mesh.vertex(e, 0).idx()], index[mesh.vertex(e, 1).idx()]});
    }
    model.faces.reserve(mesh.n_faces());
    for (MeshIndex i = 0; i < mesh.faces_size(); ++i)
    {
        const Face f(i);
        if (mesh.is_deleted(f))
            continue;
        std::vector<uint32_t> poly;
        const Halfedge start = mesh.halfedge(f);
        Halfedge h = start;
        do
        {
            poly.push_back(index[mesh.from_vertex(h).idx()]);
            h = mesh.next(h);
        } while (h != start);
        model.faces.push_back(std::move(poly));
    }
    return model;
}

} // namespace zomeify
