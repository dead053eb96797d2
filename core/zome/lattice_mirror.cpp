#include "core/zome/lattice_mirror.h"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace zomeify {

ZVec LatticeMirror::reflect(const ZVec& p) const
{
    std::array<QPhi, 3> t = {p.twice(0), p.twice(1), p.twice(2)};
    t[axis] = sum - t[axis];
    return ZVec::from_twice(t[0], t[1], t[2]);
}

namespace {

//! Per ball the index of its image, or -1; and how many have none.
std::pair<std::vector<int64_t>, size_t> images(const ZomeModel& model, const LatticeMirror& mirror)
{
    std::unordered_map<ZVec, uint32_t, ZVecHash> index;
    for (uint32_t i = 0; i < model.nodes.size(); ++i)
        index.emplace(model.nodes[i], i);
    std::vector<int64_t> image(model.nodes.size(), -1);
    size_t missing = 0;
    for (uint32_t i = 0; i < model.nodes.size(); ++i)
        if (const auto it = index.find(mirror.reflect(model.nodes[i])); it != index.end())
            image[i] = it->second;
        else
            ++missing;
    return {std::move(image), missing};
}

} // namespace

std::optional<std::vector<uint32_t>> mirror_ball_images(const ZomeModel& model, const LatticeMirror& mirror)
{
    const auto [image, missing] = images(model, mirror);
    if (missing)
        return std::nullopt;
    return std::vector<uint32_t>(image.begin(), image.end());
}

MirrorMismatch mirror_mismatch(const ZomeModel& model, const LatticeMirror& mirror)
{
    MirrorMismatch out;
    const auto [image, missing] = images(model, mirror);
    out.balls = missing;
    const auto key = [](uint64_t a, uint64_t b) { return std::min(a, b) << 32 | std::max(a, b); };
    std::unordered_set<uint64_t> struts;
    for (const auto& s : model.struts)
        struts.insert(key(s[0], s[1]));
    for (const auto& s : model.struts)
        if (image[s[0]] < 0 || image[s[1]] < 0 ||
            !struts.contains(key(static_cast<uint64_t>(image[s[0]]), static_cast<uint64_t>(image[s[1]]))))
            ++out.struts;
    return out;
}

LatticeMirror middle_plane(const ZomeModel& model, int axis)
{
    QPhi lo = model.nodes.at(0).twice(axis), hi = lo;
    for (const ZVec& p : model.nodes)
    {
        const QPhi t = p.twice(axis);
        if (t.to_double() < lo.to_double())
            lo = t;
        if (t.to_double() > hi.to_double())
            hi = t;
    }
    return {axis, lo + hi};
}

std::optional<ModelMirror> model_mirror(const ZomeModel& model)
{
    if (model.nodes.empty())
        return std::nullopt;
    std::optional<ModelMirror> best;
    for (int axis = 0; axis < 3; ++axis)
    {
        const LatticeMirror mirror = middle_plane(model, axis);
        const MirrorMismatch m = mirror_mismatch(model, mirror);
        if (!best || m.balls < best->mismatch.balls ||
            (m.balls == best->mismatch.balls && m.struts < best->mismatch.struts))
            best = ModelMirror{mirror, m};
    }
    return best;
}

} // namespace zomeify
