#include "core/cli/run_kits.h"

#include <cmath>

#include "core/assembly/real_size.h"
#include "core/pipeline/pipeline.h"

namespace zomeify::cli {

std::string owned_text(const OwnedKits& owned)
{
    std::string s;
    for (const auto& [kit, n] : owned)
        s += (s.empty() ? "" : " + ") + std::to_string(n) + " x " + std::string(kit->name);
    return s;
}

int fit_max_resolution(const Args& args, double mesh_longest_side)
{
    double b1 = 0.0;
    if (args.has("--size-cm"))
        b1 = b1_for_size_cm(mesh_longest_side, args.number("--size-cm", 0.0, -1e300, 1e300));
    else if (args.has("--b1"))
        b1 = args.number("--b1", 0.0, 0.0, 1e300);
    else if (args.has("--resolution") && args.value("--resolution") != std::optional<std::string>("auto"))
        return static_cast<int>(args.integer("--resolution", 0, kMinResolution, kMaxResolution));
    if (b1 > 0.0)
        return std::clamp(static_cast<int>(std::floor(mesh_longest_side / b1)), kMinResolution, kMaxResolution);
    return kFitMaxResolution;
}

std::string estimate_fit_line(size_t balls, const PartCounts& have)
{
    const PartCounts typical = part_counts(typical_parts(balls));
    return "Estimate: a model of about " + std::to_string(balls) + " balls typically " +
           (fits(typical, have) ? std::string("fits your kits")
                                : "does not fit your kits (" + fit_text(typical, have) + ")") +
           "; checked again on the result.";
}

} // namespace zomeify::cli
