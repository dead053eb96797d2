#include "core/anneal/energy_state.h"

namespace zomeify {

EnergyState::EnergyState(const ZomeMesh& mesh, const SurfaceContext& context, const EnergyOptions& options)
    : context_(context), options_(options)
{
    reset(mesh);
}

void EnergyState::reset(const ZomeMesh& mesh)
{
    sums_ = evaluate_energy(mesh, context_, options_).sums;
}

bool EnergyState::commit(const EnergyDelta& delta) noexcept
{
    if (!delta.ok())
    {
        return false;
    }
    sums_ += delta.sums;
    return true;
}

} // namespace zomeify
