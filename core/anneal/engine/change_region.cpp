#include "core/anneal/engine/change_region.h"

#include <exception>

#include "core/mesh/circulators.h"

namespace zomeify {

namespace {

bool in_sphere(const ChangeRegion& region, const ZVec& p) noexcept
{
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
        const double d = p.coord(k) - region.centre[static_cast<size_t>(k)];
        d2 += d * d;
    }
    return d2 <= region.radius * region.radius;
}

} // namespace

bool in_region(const ChangeRegion& region, const ZVec& p) noexcept
{
    if (in_sphere(region, p))
        return true;
    if (!region.mirror)
        return false;
    try
    {
        return in_sphere(region, region.mirror->reflect(p));
    }
    catch (const std::exception&) // an image beyond int32 lies nowhere near the region
    {
        return false;
    }
}

bool region_allows(const ZomeMesh& mesh, const LocalChange& change, const ChangeRegion& region) noexcept
{
    const auto inside = [&](Vertex v) { return in_region(region, mesh.position(v)); };
    for (Vertex v : change.removed_nodes())
        if (!inside(v))
            return false;
    for (const ZVec& p : change.added_nodes())
        if (!in_region(region, p))
            return false;
    for (Edge e : change.removed_struts())
        if (!inside(mesh.vertex(e, 0)) && !inside(mesh.vertex(e, 1)))
            return false;
    for (Face f : change.removed_faces())
    {
        bool touches = false;
        for (Vertex v : face_vertices(mesh, f))
            touches = touches || inside(v);
        if (!touches)
            return false;
    }
    for (const NewStrut& s : change.added_struts())
        if (!in_region(region, s.a) && !in_region(region, s.b))
            return false;
    for (const NewFace& f : change.added_faces())
    {
        bool touches = false;
        for (const ZVec& p : f.view())
            touches = touches || in_region(region, p);
        if (!touches)
            return false;
    }
    return true;
}

} // namespace zomeify
