#include "core/zome/symmetry.h"

namespace zomeify {

namespace {

// Halves a number known to be twice an element of the 6-integer form's coordinate ring.
std::optional<QPhi> half(QPhi x)
{
    if (!x.both_even())
        return std::nullopt;
    return QPhi{x.a / 2, x.b / 2};
}

std::optional<ZVec> from_four_times(QPhi x4, QPhi y4, QPhi z4)
{
    // We hold 4·(component); the 6-integer form wants 2·(component).
    auto x = half(x4), y = half(y4), z = half(z4);
    if (!x || !y || !z)
        return std::nullopt;
    return ZVec::from_twice(*x, *y, *z);
}

std::optional<Rotation> frame_rotation(const ZVec& u, const ZVec& v, const ZVec& w)
{
    Rotation r{{u, v, w}, {}};
    for (int s = 0; s < kSlotCount; ++s)
    {
        for (int size = 0; size < kSizeCount; ++size)
        {
            const auto image = r.apply(zome_vector(vector_id(s, size)));
            if (!image)
                return std::nullopt;
            const int id = vector_id_of(*image);
            if (id < 0 || vector_size(id) != size)
                return std::nullopt;
            if (size == 0)
                r.slot_map[static_cast<size_t>(s)] = static_cast<uint8_t>(vector_slot(id));
        }
    }
    return r;
}

} // namespace

std::optional<ZVec> cross(const ZVec& u, const ZVec& v)
{
    // (2u) × (2v) = 4 (u × v).
    const QPhi x = u.twice(1) * v.twice(2) - u.twice(2) * v.twice(1);
    const QPhi y = u.twice(2) * v.twice(0) - u.twice(0) * v.twice(2);
    const QPhi z = u.twice(0) * v.twice(1) - u.twice(1) * v.twice(0);
    return from_four_times(x, y, z);
}

std::optional<ZVec> Rotation::apply(const ZVec& v) const
{
    // R v = Σ_k v_k · column_k; with twice-values: 4 (R v) = Σ (2 v_k)(2 column_k).
    QPhi out[3];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            out[i] = out[i] + v.twice(k) * columns[static_cast<size_t>(k)].twice(i);
    return from_four_times(out[0], out[1], out[2]);
}

const std::vector<Rotation>& zome_rotations()
{
    static const std::vector<Rotation> rotations = [] {
        std::vector<Rotation> found;
        const ZVec ex = zome_vector(vector_id(0, 0));
        for (int a = 0; a < kBlueSlots; ++a)
            for (int b = 0; b < kBlueSlots; ++b)
            {
                const ZVec& u = zome_vector(vector_id(a, 0));
                const ZVec& v = zome_vector(vector_id(b, 0));
                if (!dot4(u, v).is_zero())
                    continue;
                const auto w = cross(u, v);
                if (!w)
                    continue;
                if (auto r = frame_rotation(u, v, *w))
                    found.push_back(*r);
            }
        // Keep the identity first.
        for (size_t i = 0; i < found.size(); ++i)
            if (found[i].columns[0] == ex && found[i].columns[1] == ZVec{{0, 0, 0, 2, 0, 0}})
                std::swap(found[0], found[i]);
        return found;
    }();
    return rotations;
}

} // namespace zomeify
