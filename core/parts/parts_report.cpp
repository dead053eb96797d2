#include "core/parts/parts_report.h"

#include <cctype>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/base/errors.h"

namespace zomeify {

namespace {

std::string trim(const std::string& s)
{
    size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a])))
        ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1])))
        --b;
    return s.substr(a, b - a);
}

} // namespace

OwnedKits parse_owned_kits(const std::string& text)
{
    OwnedKits owned;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
    {
        item = trim(item);
        if (item.empty())
            continue;
        size_t count = 1, i = 0;
        if (std::isdigit(static_cast<unsigned char>(item[0])))
        {
            count = 0;
            while (i < item.size() && std::isdigit(static_cast<unsigned char>(item[i])) && count < 100000)
                count = count * 10 + static_cast<size_t>(item[i++] - '0');
            item = trim(item.substr(i));
            if (!item.empty() && (item[0] == 'x' || item[0] == 'X' || item[0] == '*'))
                item = trim(item.substr(1));
            if (count == 0 || count >= 100000)
                throw InvalidInputError("kit count in '" + text + "' must be between 1 and 99999");
        }
        owned.push_back({&find_kit(item), count});
    }
    return owned;
}

std::string parts_report_text(const PartsList& parts, const OwnedKits& owned)
{
    std::string out = parts_table(parts) + kit_plan_text(plan_kits(parts));
    if (!owned.empty())
        out += "missing with your kits: " + part_counts_text(missing_parts(parts, owned)) + "\n";
    return out;
}

nlohmann::json part_counts_json(const PartCounts& c)
{
    nlohmann::json j = nlohmann::json::object();
    for (int k = 0; k < kStrutKindCount; ++k)
        j[std::string(kind_info(static_cast<StrutKind>(k)).name)] = c[static_cast<size_t>(k)];
    j["balls"] = c[kStrutKindCount];
    return j;
}

std::string parts_report_json(const PartsList& parts, const OwnedKits& owned)
{
    nlohmann::json doc = nlohmann::json::parse(parts_json(parts));
    const KitPlan plan = plan_kits(parts);
    nlohmann::json kits = nlohmann::json::array();
    for (const auto& [kit, n] : plan.kits)
        kits.push_back({{"kit", kit->id}, {"name", kit->name}, {"count", n}});
    doc["kit_plan"] = {{"kits", kits}, {"parts_bought", plan.parts_bought}, {"spare", part_counts_json(plan.spare)}};
    if (!owned.empty())
    {
        nlohmann::json have = nlohmann::json::array();
        for (const auto& [kit, n] : owned)
            have.push_back({{"kit", kit->id}, {"count", n}});
        doc["owned_kits"] = have;
        doc["missing"] = part_counts_json(missing_parts(parts, owned));
    }
    return doc.dump(2) + "\n";
}

} // namespace zomeify
