#pragma once
//! \file torus_surface.h
//! A torus (genus 1) with what the pipeline builds for a surface, its projector and inside test,
//! and its Z0 at a resolution keeping the hole: shared by the tests of the kits before a run.

#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/voxel/initial_model.h"
#include "tests/support/geom_fixtures.h"

namespace zomeify::test {

struct TorusSurface
{
    TriangleMesh mesh = make_torus(3.0, 1.2, 48, 24);
    SurfaceProjector projector{mesh};
    InsideTest inside{projector};

    InsidePredicate is_inside() const
    {
        return [this](const Vec3& p) { return inside.is_inside(p); };
    }
    InitialModel z0(int resolution) const
    {
        InitialModelOptions o;
        o.resolution = resolution;
        o.target_genus = 1;
        o.surface_probe = probe_of(projector);
        return build_initial_model(mesh, is_inside(), o);
    }
};

} // namespace zomeify::test
