#include "core/pipeline/z0_choice.h"

namespace zomeify {

InitialModelOptions run_z0_options(const SurfaceProjector& projector, long long genus, int resolution, double b1)
{
    InitialModelOptions o;
    o.resolution = resolution;
    o.b1 = b1;
    // A grid a few percent off (a nudge), or the grid carved freely, often keeps a handle the exact
    // grid closes or bridges.
    o.target_genus = genus;
    o.surface_probe = probe_of(projector);
    return o;
}

} // namespace zomeify
