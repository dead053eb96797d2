#include "core/parts/mirror_halves.h"

#include <numeric>
#include <sstream>

#include "core/zome/slots.h"

namespace zomeify {
namespace {

size_t strut_total(const PartCounts& c) { return std::accumulate(c.begin(), c.begin() + kStrutKindCount, size_t{0}); }

// -1: the half on the low side; 0: on the plane; 1: the other half.
int side(const LatticeMirror& m, const ZVec& p)
{
    const double twice = 2.0 * p.twice(m.axis).to_double(), sum = m.sum.to_double();
    return m.on_plane(p) ? 0 : twice < sum ? -1 : 1;
}

nlohmann::json counts_json(const PartCounts& c)
{
    nlohmann::json struts = nlohmann::json::object();
    for (int k = 0; k < kStrutKindCount; ++k)
        struts[std::string(kind_info(static_cast<StrutKind>(k)).name)] = c[static_cast<size_t>(k)];
    return {{"balls", c[kStrutKindCount]}, {"struts", struts}, {"strut_count", strut_total(c)}};
}

std::string counts_text(const PartCounts& c)
{
    std::ostringstream s;
    s << c[kStrutKindCount] << " balls, " << strut_total(c) << " struts (";
    bool first = true;
    for (int k = 0; k < kStrutKindCount; ++k)
        if (const size_t n = c[static_cast<size_t>(k)])
        {
            s << (first ? "" : ", ") << kind_info(static_cast<StrutKind>(k)).name << " " << n;
            first = false;
        }
    s << ")";
    return s.str();
}

} // namespace

std::optional<MirrorHalves> mirror_halves(const ZomeModel& model)
{
    const std::optional<ModelMirror> own = model_mirror(model);
    if (!own || !own->mismatch.symmetric())
        return std::nullopt;
    MirrorHalves h;
    h.mirror = own->mirror;
    for (const ZVec& p : model.nodes)
    {
        const int s = side(h.mirror, p);
        if (s == 0)
            ++h.middle[kStrutKindCount];
        else if (s < 0)
            ++h.half[kStrutKindCount];
    }
    for (const auto& st : model.struts)
    {
        const ZVec &a = model.nodes[st[0]], &b = model.nodes[st[1]];
        const int id = vector_id_of(b - a);
        if (id < 0)
            return std::nullopt; // not a Zome model: parts_list says so
        const size_t kind = static_cast<size_t>(vector_kind(id));
        const int sa = side(h.mirror, a), sb = side(h.mirror, b);
        if (sa < 0 || sb < 0)
            (sa > 0 || sb > 0 ? h.middle : h.half)[kind] += 1; // across the plane, or in the low half
        else if (sa == 0 && sb == 0)
            ++h.middle[kind];
    }
    return h;
}

std::string mirror_halves_text(const MirrorHalves& h)
{
    return std::string("mirror-symmetric (about a plane across the ") + "xyz"[h.mirror.axis] +
           " axis): build one half, " + counts_text(h.half) +
           ", twice (the second mirrored, the same parts), and "
           "the middle, " +
           counts_text(h.middle) + ", on the plane or across it\n";
}

nlohmann::json mirror_halves_json(const MirrorHalves& h)
{
    return {{"axis", std::string(1, "xyz"[h.mirror.axis])},
            {"coordinate_b0", h.mirror.coordinate()},
            {"half", counts_json(h.half)},
            {"middle", counts_json(h.middle)}};
}

} // namespace zomeify
