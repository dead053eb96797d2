#include "core/anneal/engine/part_tally.h"

namespace zomeify {

PartTally::PartTally(const ZomeMesh& mesh)
{
    for (MeshIndex i = 0; i < mesh.edges_size(); ++i)
        if (const Edge e(i); !mesh.is_deleted(e))
            ++counts_[static_cast<size_t>(mesh.kind(e))];
    counts_[kStrutKindCount] = static_cast<int64_t>(mesh.n_vertices());
}

PartTally::Counts PartTally::change_of(const ZomeMesh& mesh, const LocalChange& change) noexcept
{
    Counts d{};
    for (Edge e : change.removed_struts())
        --d[static_cast<size_t>(mesh.kind(e))];
    for (const NewStrut& s : change.added_struts())
        if (const int id = vector_id_of(s.b - s.a); id >= 0)
            ++d[static_cast<size_t>(vector_kind(id))];
    d[kStrutKindCount] =
        static_cast<int64_t>(change.added_nodes().size()) - static_cast<int64_t>(change.removed_nodes().size());
    return d;
}

bool PartTally::allows(const Counts& delta, const PartLimits& limits) const noexcept
{
    for (size_t k = 0; k < counts_.size(); ++k)
    {
        const int64_t limit = k < kStrutKindCount ? limits.struts[k] : limits.balls;
        if (delta[k] > 0 && counts_[k] + delta[k] > limit)
            return false;
    }
    return true;
}

void PartTally::apply(const Counts& delta) noexcept
{
    for (size_t k = 0; k < counts_.size(); ++k)
        counts_[k] += delta[k];
}

} // namespace zomeify
