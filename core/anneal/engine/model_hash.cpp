#include "core/anneal/engine/model_hash.h"

#include <algorithm>
#include <cstring>
#include <utility>
#include <vector>

#include "core/base/hash.h"

namespace zomeify {

namespace {

class Hasher
{
public:
    void add(uint64_t x) noexcept { h_ = mix64(h_ ^ (x + 0x9E3779B97F4A7C15ULL)); }
    void add(const ZVec& p) noexcept
    {
        for (int32_t c : p.c)
            add(static_cast<uint64_t>(static_cast<uint32_t>(c)));
    }
    void add_double(double x) noexcept
    {
        // memcpy, not std::bit_cast: Emscripten 3.1.6's libc++ has no bit_cast.
        uint64_t bits = 0;
        std::memcpy(&bits, &x, sizeof bits);
        add(bits);
    }
    uint64_t value() const noexcept { return h_; }

private:
    uint64_t h_ = 0x5A6F6D6548617368ULL;
};

} // namespace

uint64_t canonical_model_hash(const ZomeModel& model)
{
    Hasher h;
    std::vector<ZVec> nodes = model.nodes;
    std::sort(nodes.begin(), nodes.end());
    h.add(static_cast<uint64_t>(nodes.size()));
    for (const ZVec& p : nodes)
        h.add(p);

    std::vector<std::pair<ZVec, ZVec>> struts;
    struts.reserve(model.struts.size());
    for (const auto& s : model.struts)
    {
        if (s[0] >= model.nodes.size() || s[1] >= model.nodes.size())
            continue;
        ZVec a = model.nodes[s[0]], b = model.nodes[s[1]];
        if (b < a)
            std::swap(a, b);
        struts.emplace_back(a, b);
    }
    std::sort(struts.begin(), struts.end(), [](const auto& x, const auto& y) {
        return x.first < y.first || (x.first == y.first && x.second < y.second);
    });
    h.add(static_cast<uint64_t>(struts.size()));
    for (const auto& [a, b] : struts)
    {
        h.add(a);
        h.add(b);
    }

    std::vector<std::vector<ZVec>> faces;
    faces.reserve(model.faces.size());
    for (const auto& f : model.faces)
    {
        std::vector<ZVec> cycle;
        for (uint32_t v : f)
            if (v < model.nodes.size())
                cycle.push_back(model.nodes[v]);
        if (cycle.empty())
            continue;
        std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
        faces.push_back(std::move(cycle));
    }
    std::sort(faces.begin(), faces.end(), [](const auto& x, const auto& y) {
        return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end());
    });
    h.add(static_cast<uint64_t>(faces.size()));
    for (const auto& f : faces)
    {
        h.add(static_cast<uint64_t>(f.size()));
        for (const ZVec& p : f)
            h.add(p);
    }

    h.add_double(model.transform.scale);
    for (double t : model.transform.translation)
        h.add_double(t);
    return h.value();
}

} // namespace zomeify
