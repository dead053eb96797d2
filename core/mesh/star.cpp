#include "core/mesh/star.h"

#include "core/mesh/small_buffer.h"
#include "core/mesh/topology_error.h"

namespace zomeify {

bool vertex_link(const SurfaceMesh& mesh, Vertex v, std::vector<Vertex>& link)
{
    link.clear();
    const Halfedge start = mesh.halfedge(v);
    // halfedge(v) is a boundary halfedge whenever v has one, so this one test covers the rotation.
    if (!start.is_valid() || mesh.is_boundary(start))
        return false;
    Halfedge h = start;
    do
    {
        const Halfedge last = mesh.prev(h);
        for (Halfedge x = mesh.next(h); x != last; x = mesh.next(x))
            link.push_back(mesh.from_vertex(x));
        h = mesh.ccw_rotated(h);
    } while (h != start);
    return true;
}

bool edge_link(const SurfaceMesh& mesh, Edge e, std::vector<Vertex>& link)
{
    link.clear();
    if (mesh.is_boundary(e))
        return false;
    for (int side = 0; side < 2; ++side)
    {
        const Halfedge h = SurfaceMesh::halfedge(e, side);
        for (Halfedge x = mesh.next(h); x != h; x = mesh.next(x))
            link.push_back(mesh.from_vertex(x));
    }
    return true;
}

bool is_simple_loop(std::span<const Vertex> loop)
{
    // Links have a handful of nodes: the quadratic scan beats any hashing.
    for (size_t i = 0; i < loop.size(); ++i)
        for (size_t j = i + 1; j < loop.size(); ++j)
            if (loop[i] == loop[j])
                return false;
    return true;
}

void clear_vertex_star(SurfaceMesh& mesh, Vertex v)
{
    if (!mesh.is_valid(v))
        throw TopologyError("clear_vertex_star: invalid or deleted vertex");
    detail::SmallBuffer<Face, 16> faces;
    const Halfedge start = mesh.halfedge(v);
    if (!start.is_valid())
        return;
    Halfedge h = start;
    do
    {
        if (!mesh.is_boundary(h))
            faces.push_back(mesh.face(h));
        h = mesh.ccw_rotated(h);
    } while (h != start);
    for (Face f : faces)
        mesh.remove_face(f);
}

void clear_edge_star(SurfaceMesh& mesh, Edge e)
{
    if (!mesh.is_valid(e))
        throw TopologyError("clear_edge_star: invalid or deleted edge");
    const Face f0 = mesh.face(SurfaceMesh::halfedge(e, 0));
    const Face f1 = mesh.face(SurfaceMesh::halfedge(e, 1));
    if (f0.is_valid())
        mesh.remove_face(f0);
    if (f1.is_valid() && f1 != f0)
        mesh.remove_face(f1);
}

} // namespace zomeify
