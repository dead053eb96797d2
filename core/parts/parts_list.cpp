#include "core/parts/parts_list.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/base/errors.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

PartsList parts_list(const ZomeModel& model)
{
    PartsList parts;
    parts.balls = model.nodes.size();
    for (size_t s = 0; s < model.struts.size(); ++s)
    {
        const auto& st = model.struts[s];
        if (st[0] >= model.nodes.size() || st[1] >= model.nodes.size())
            throw InvalidInputError("strut " + std::to_string(s) + " refers to a missing node");
        const int id = vector_id_of(model.nodes[st[1]] - model.nodes[st[0]]);
        if (id < 0)
            throw InvalidInputError("strut " + std::to_string(s) + " is not a Zome strut");
        const StrutKind kind = vector_kind(id);
        ++parts.struts[static_cast<size_t>(kind)];
        parts.total_length_b0 += kind_info(kind).length;
    }
    parts.strut_count = model.struts.size();
    parts.total_length_mm = parts.total_length_b0 * kMmPerB0;
    if (!model.nodes.empty())
    {
        for (int k = 0; k < 3; ++k)
        {
            double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
            for (const ZVec& p : model.nodes)
            {
                lo = std::min(lo, p.coord(k));
                hi = std::max(hi, p.coord(k));
            }
            parts.size_cm[static_cast<size_t>(k)] = ((hi - lo) * kMmPerB0 + kBallDiameterMm) / 10.0;
        }
    }
    return parts;
}

std::string parts_table(const PartsList& parts)
{
    std::ostringstream out;
    char line[160];
    std::snprintf(line, sizeof line, "%-12s %-6s %-7s %10s %7s\n", "part", "kind", "colour", "length mm", "count");
    out << line;
    std::snprintf(line, sizeof line, "%-12s %-6s %-7s %10.2f %7zu\n", kBallPartCode, "ball", "white", kBallDiameterMm,
                  parts.balls);
    out << line;
    for (int k = 0; k < kStrutKindCount; ++k)
    {
        const StrutKindInfo& info = kind_info(static_cast<StrutKind>(k));
        const size_t n = parts.struts[static_cast<size_t>(k)];
        if (n == 0)
            continue;
        std::snprintf(line, sizeof line, "%-12s %-6s %-7s %10.2f %7zu\n", std::string(info.part_code).c_str(),
                      std::string(info.name).c_str(), std::string(info.color).c_str(), info.length_mm, n);
        out << line;
    }
    std::snprintf(line, sizeof line,
                  "total: %zu balls, %zu struts, %.2f m of struts; built size %.1f x %.1f x %.1f cm\n", parts.balls,
                  parts.strut_count, parts.total_length_mm / 1000.0, parts.size_cm[0], parts.size_cm[1],
                  parts.size_cm[2]);
    out << line;
    return out.str();
}

std::string parts_csv(const PartsList& parts)
{
    std::ostringstream out;
    char line[160];
    out << "part_code,kind,color,length_mm,count\n";
    std::snprintf(line, sizeof line, "%s,ball,white,%.2f,%zu\n", kBallPartCode, kBallDiameterMm, parts.balls);
    out << line;
    for (int k = 0; k < kStrutKindCount; ++k)
    {
        const StrutKindInfo& info = kind_info(static_cast<StrutKind>(k));
        std::snprintf(line, sizeof line, "%s,%s,%s,%.2f,%zu\n", std::string(info.part_code).c_str(),
                      std::string(info.name).c_str(), std::string(info.color).c_str(), info.length_mm,
                      parts.struts[static_cast<size_t>(k)]);
        out << line;
    }
    return out.str();
}

std::string parts_json(const PartsList& parts)
{
    using nlohmann::json;
    json counts = json::object();
    json kinds = json::array();
    for (int k = 0; k < kStrutKindCount; ++k)
    {
        const StrutKindInfo& info = kind_info(static_cast<StrutKind>(k));
        const size_t n = parts.struts[static_cast<size_t>(k)];
        counts[std::string(info.name)] = n;
        kinds.push_back({{"kind", info.name},
                         {"color", info.color},
                         {"part_code", info.part_code},
                         {"length_mm", std::round(info.length_mm * 100) / 100},
                         {"count", n}});
    }
    const json doc = {
        {"balls", parts.balls},
        {"ball_part_code", kBallPartCode},
        {"struts", counts},
        {"strut_count", parts.strut_count},
        {"kinds", kinds},
        {"total_strut_length_b0", parts.total_length_b0},
        {"total_strut_length_mm", parts.total_length_mm},
        {"size_cm", parts.size_cm},
    };
    return doc.dump(2) + "\n";
}

} // namespace zomeify
