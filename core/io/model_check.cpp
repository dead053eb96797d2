#include "core/io/model_check.h"

#include <string>
#include <unordered_map>
#include <unordered_set>

#include "core/base/errors.h"
#include "core/zome/slots.h"

namespace zomeify {

namespace {

std::string strut_name(size_t s, const std::array<uint32_t, 2>& st)
{
    return "strut " + std::to_string(s) + " (nodes " + std::to_string(st[0]) + "-" + std::to_string(st[1]) + ")";
}

} // namespace

void check_model(const ZomeModel& model)
{
    const size_t n = model.nodes.size();
    if (n > kMaxModelNodes)
        throw InvalidInputError("too many nodes: " + std::to_string(n) + " (limit " + std::to_string(kMaxModelNodes) +
                                ")");
    if (model.struts.size() > kMaxModelStruts)
        throw InvalidInputError("too many struts: " + std::to_string(model.struts.size()));
    if (model.faces.size() > kMaxModelFaces)
        throw InvalidInputError("too many faces: " + std::to_string(model.faces.size()));

    std::unordered_map<ZVec, size_t, ZVecHash> position_owner;
    position_owner.reserve(n);
    for (size_t i = 0; i < n; ++i)
    {
        const auto [it, inserted] = position_owner.try_emplace(model.nodes[i], i);
        if (!inserted)
            throw InvalidInputError("nodes " + std::to_string(it->second) + " and " + std::to_string(i) +
                                    " are at the same position");
    }

    // Slot occupancy per node: 62 bits each.
    std::vector<uint64_t> used_slots(n, 0);
    std::unordered_set<uint64_t> seen_struts;
    seen_struts.reserve(model.struts.size());
    for (size_t s = 0; s < model.struts.size(); ++s)
    {
        const auto& st = model.struts[s];
        if (st[0] >= n || st[1] >= n)
            throw InvalidInputError(strut_name(s, st) + " refers to a node that does not exist (" + std::to_string(n) +
                                    " nodes)");
        if (st[0] == st[1])
            throw InvalidInputError(strut_name(s, st) + " joins a node to itself");
        const ZVec v = model.nodes[st[1]] - model.nodes[st[0]];
        const int id = vector_id_of(v);
        if (id < 0)
        {
            const auto d = v.to_double();
            throw InvalidInputError(strut_name(s, st) + " is not a Zome strut (vector " + std::to_string(d[0]) + ", " +
                                    std::to_string(d[1]) + ", " + std::to_string(d[2]) + ")");
        }
        const uint64_t lo = std::min(st[0], st[1]), hi = std::max(st[0], st[1]);
        if (!seen_struts.insert(lo << 32 | hi).second)
            throw InvalidInputError(strut_name(s, st) + " appears twice");
        const int slot = vector_slot(id);
        const uint64_t bit_from = uint64_t{1} << slot, bit_to = uint64_t{1} << opposite_slot(slot);
        if ((used_slots[st[0]] & bit_from) || (used_slots[st[1]] & bit_to))
            throw InvalidInputError(strut_name(s, st) + " uses a ball hole that another strut already uses");
        used_slots[st[0]] |= bit_from;
        used_slots[st[1]] |= bit_to;
    }

    for (size_t f = 0; f < model.faces.size(); ++f)
    {
        const auto& face = model.faces[f];
        if (face.size() < 3 || face.size() > kMaxFaceSize)
            throw InvalidInputError("face " + std::to_string(f) + " has " + std::to_string(face.size()) + " corners");
        for (uint32_t v : face)
            if (v >= n)
                throw InvalidInputError("face " + std::to_string(f) + " refers to node " + std::to_string(v) +
                                        " that does not exist");
    }
}

} // namespace zomeify
