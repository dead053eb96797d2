#include "core/anneal/energy/energy_state.h"

namespace zomeify {

EnergyState::EnergyState(const ZomeMesh& mesh, const SurfaceContext& context, const EnergyOptions& options)
    : context_(context), options_(options), surface_(context, options)
{
    reset(mesh);
}

void EnergyState::reset(const ZomeMesh& mesh)
{
    sums_ = evaluate_local_sums(mesh, context_, options_);
    surface_.reset(mesh);
    sums_.surface = surface_.sum();
    sums_.surface_samples = static_cast<int64_t>(surface_.sample_count());
}

bool EnergyState::commit(const EnergyDelta& delta, std::span<const Face> added_faces, SurfaceChange& scratch)
{
    if (!delta.ok())
    {
        return false;
    }
    sums_ += delta.sums;
    surface_.commit(scratch, added_faces);
    return true;
}

} // namespace zomeify
