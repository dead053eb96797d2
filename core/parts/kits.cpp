#include "core/parts/kits.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <sstream>

#include "core/base/errors.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

std::string normalised(std::string_view s)
{
    std::string out;
    for (char c : s)
        if (!std::isspace(static_cast<unsigned char>(c)) && c != '-' && c != '_')
            out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    return out;
}

size_t ceil_div(size_t a, size_t b) { return (a + b - 1) / b; }

// Need per colour: a kit holds the same number of each length, so only the largest length counts.
std::array<size_t, 4> colour_needs(const PartCounts& need)
{
    std::array<size_t, 4> c{};
    for (int k = 0; k < kStrutKindCount; ++k)
        c[static_cast<size_t>(k / kSizeCount)] =
            std::max(c[static_cast<size_t>(k / kSizeCount)], need[static_cast<size_t>(k)]);
    c[3] = need[kStrutKindCount];
    return c;
}

} // namespace

const std::vector<Kit>& standard_kits()
{
    // Largest first: the plan lists kits in this order.
    static const std::vector<Kit> kits = {
        {"workshop", "Workshop", {720, 640, 560}, 1000},
        {"creator3", "Creator 3", {90, 60, 36}, 180},
        {"creator1", "Creator 1", {30, 20, 12}, 60},
        {"basic", "Basic", {15, 10, 6}, 30},
    };
    return kits;
}

const Kit& find_kit(std::string_view id_or_name)
{
    const std::string want = normalised(id_or_name);
    for (const Kit& k : standard_kits())
        if (normalised(k.id) == want || normalised(k.name) == want)
            return k;
    throw InvalidInputError("unknown kit '" + std::string(id_or_name) +
                            "' (known: basic, creator1, creator3, workshop)");
}

PartCounts part_counts(const PartsList& parts)
{
    PartCounts c{};
    std::copy(parts.struts.begin(), parts.struts.end(), c.begin());
    c[kStrutKindCount] = parts.balls;
    return c;
}

PartCounts kit_contents(const std::vector<std::pair<const Kit*, size_t>>& kits)
{
    PartCounts c{};
    for (const auto& [kit, n] : kits)
    {
        for (int k = 0; k < kStrutKindCount; ++k)
            c[static_cast<size_t>(k)] += n * kit->struts_per_length[static_cast<size_t>(k / kSizeCount)];
        c[kStrutKindCount] += n * kit->balls;
    }
    return c;
}

KitPlan plan_kits(const PartsList& parts)
{
    const auto& kits = standard_kits();
    const std::array<size_t, 4> need = colour_needs(part_counts(parts));
    auto covers_count = [&](const Kit& k) {
        size_t n = 0;
        for (size_t c = 0; c < 3; ++c)
            n = std::max(n, ceil_div(need[c], k.struts_per_length[c]));
        return std::max(n, ceil_div(need[3], k.balls));
    };
    // Exhaustive over Workshop and Creator 3 counts (each bounded by the count that alone covers
    // the model). A Creator 3 holds exactly three Creator 1 and a Creator 1 two Basic kits, so
    // an optimum with fewest kits never needs more than two Creator 1; the number of Basic kits
    // is then the least that completes the cover.
    std::array<size_t, 4> best{};
    size_t best_parts = std::numeric_limits<size_t>::max(), best_kits = best_parts;
    const size_t max_w = covers_count(kits[0]), max_c3 = covers_count(kits[1]),
                 max_c1 = std::min<size_t>(2, covers_count(kits[2]));
    for (size_t w = 0; w <= max_w; ++w)
        for (size_t c3 = 0; c3 <= max_c3; ++c3)
            for (size_t c1 = 0; c1 <= max_c1; ++c1)
            {
                size_t basic = 0;
                for (size_t c = 0; c < 4; ++c)
                {
                    const size_t have = c < 3 ? w * kits[0].struts_per_length[c] + c3 * kits[1].struts_per_length[c] +
                                                    c1 * kits[2].struts_per_length[c]
                                              : w * kits[0].balls + c3 * kits[1].balls + c1 * kits[2].balls;
                    const size_t per_basic = c < 3 ? kits[3].struts_per_length[c] : kits[3].balls;
                    if (have < need[c])
                        basic = std::max(basic, ceil_div(need[c] - have, per_basic));
                }
                const size_t bought = w * kits[0].part_count() + c3 * kits[1].part_count() + c1 * kits[2].part_count() +
                                      basic * kits[3].part_count();
                const size_t count = w + c3 + c1 + basic;
                if (bought < best_parts || (bought == best_parts && count < best_kits))
                {
                    best = {w, c3, c1, basic};
                    best_parts = bought;
                    best_kits = count;
                }
            }
    KitPlan plan;
    for (size_t i = 0; i < 4; ++i)
        if (best[i] > 0)
            plan.kits.push_back({&kits[i], best[i]});
    plan.parts_bought = best_parts;
    const PartCounts have = kit_contents(plan.kits), used = part_counts(parts);
    for (size_t k = 0; k < have.size(); ++k)
        plan.spare[k] = have[k] - used[k];
    return plan;
}

PartCounts missing_parts(const PartsList& parts, const std::vector<std::pair<const Kit*, size_t>>& owned)
{
    const PartCounts have = kit_contents(owned), need = part_counts(parts);
    PartCounts missing{};
    for (size_t k = 0; k < need.size(); ++k)
        missing[k] = need[k] > have[k] ? need[k] - have[k] : 0;
    return missing;
}

std::string part_counts_text(const PartCounts& counts)
{
    std::ostringstream out;
    bool any = false;
    for (int k = 0; k < kStrutKindCount; ++k)
        if (counts[static_cast<size_t>(k)] > 0)
        {
            out << (any ? ", " : "") << counts[static_cast<size_t>(k)] << " "
                << kind_info(static_cast<StrutKind>(k)).name;
            any = true;
        }
    if (counts[kStrutKindCount] > 0)
    {
        out << (any ? ", " : "") << counts[kStrutKindCount] << " balls";
        any = true;
    }
    return any ? out.str() : "nothing";
}

std::string kit_plan_text(const KitPlan& plan)
{
    std::ostringstream out;
    out << "kit plan: ";
    for (size_t i = 0; i < plan.kits.size(); ++i)
        out << (i ? " + " : "") << plan.kits[i].second << " x " << plan.kits[i].first->name;
    if (plan.kits.empty())
        out << "nothing to buy";
    out << " (" << plan.parts_bought << " parts); left over: " << part_counts_text(plan.spare) << "\n";
    return out.str();
}

std::string kits_text(const std::vector<std::pair<const Kit*, size_t>>& kits)
{
    std::string text;
    for (const auto& [kit, n] : kits)
        text += (text.empty() ? "" : " + ") + std::to_string(n) + " " + std::string(kit->name);
    return text;
}

} // namespace zomeify
