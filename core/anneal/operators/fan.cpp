#include "core/anneal/operators/fan.h"

#include <algorithm>

#include "core/anneal/operators/exact_steps.h"

namespace zomeify::detail {

Rejection fan_fill(const ZomeMesh& mesh, const LocalChange& change, const ZVec& p, Fill& fill, size_t must_a,
                   size_t must_b) noexcept
{
    if (!position_usable(mesh, change, p))
        return Rejection::Occupied;
    const size_t k = fill.link_size();
    FixedList<uint8_t, kMaxLink> connected;
    FixedList<int, kMaxLink> slots_at_p;
    for (size_t i = 0; i < k; ++i)
    {
        const FillNode& node = fill.nodes()[i];
        const int id = vector_between(p, node.pos);
        if (id < 0)
            continue;
        const int slot = vector_slot(id);
        if (keeps_strut_in_slot(mesh, node.v, opposite_slot(slot), change))
            continue; // that link node's hole is taken: not reachable
        if (std::find(slots_at_p.begin(), slots_at_p.end(), slot) != slots_at_p.end())
            return Rejection::SlotConflict; // two link nodes in one direction from p
        slots_at_p.push_back(slot);
        connected.push_back(static_cast<uint8_t>(i));
    }
    auto is_connected = [&](size_t i) {
        return i == kNoLinkIndex || std::find(connected.begin(), connected.end(), i) != connected.end();
    };
    if (!is_connected(must_a) || !is_connected(must_b))
        return Rejection::NoCandidate;
    if (connected.size() < 3)
        return Rejection::Valence;
    const int centre = fill.add_new_node(p);
    if (centre < 0)
        return Rejection::Overflow;
    for (size_t j = 0; j < connected.size(); ++j)
    {
        const size_t from = connected[j], to = connected[(j + 1) % connected.size()];
        if ((to + k - from) % k > 2)
            return Rejection::FaceSize;
        if (!fill.add_fan_face(static_cast<size_t>(centre), from, to))
            return Rejection::Overflow;
    }
    return Rejection::None;
}

} // namespace zomeify::detail
