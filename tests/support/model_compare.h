#pragma once
//! \file model_compare.h
//! Comparison of Zome models up to the numbering of nodes, struts and face start corners
//! (what a share link keeps): positions, struts as position pairs, faces as position cycles.

#include <set>
#include <vector>

#include "core/zome/model.h"

namespace zomeify::test {

struct CanonicalModel
{
    std::set<ZVec> nodes;
    std::set<std::pair<ZVec, ZVec>> struts;
    std::set<std::vector<ZVec>> faces;
    ModelTransform transform;
    friend bool operator==(const CanonicalModel&, const CanonicalModel&) = default;
};

inline CanonicalModel canonical(const ZomeModel& m)
{
    CanonicalModel c;
    c.nodes.insert(m.nodes.begin(), m.nodes.end());
    for (const auto& s : m.struts)
    {
        ZVec a = m.nodes[s[0]], b = m.nodes[s[1]];
        if (b < a)
            std::swap(a, b);
        c.struts.insert({a, b});
    }
    for (const auto& f : m.faces)
    {
        std::vector<ZVec> cycle;
        for (uint32_t v : f)
            cycle.push_back(m.nodes[v]);
        size_t first = 0;
        for (size_t i = 1; i < cycle.size(); ++i)
            if (cycle[i] < cycle[first])
                first = i;
        std::rotate(cycle.begin(), cycle.begin() + static_cast<long>(first), cycle.end());
        c.faces.insert(cycle);
    }
    c.transform = m.transform;
    return c;
}

} // namespace zomeify::test
