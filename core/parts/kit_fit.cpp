#include "core/parts/kit_fit.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"

namespace zomeify {

namespace {

// Struts per ball, kinds B0..R2, of the bunny annealed at 11 cells for 30 s (2.7 per ball). The red
// R1 (0.31 per ball against 36 per Creator kit length) is what usually runs out first.
constexpr std::array<double, kStrutKindCount> kStrutsPerBall = {0.411, 0.534, 0.108, 0.489, 0.446,
                                                                0.129, 0.239, 0.313, 0.031};

} // namespace

PartsList typical_parts(size_t balls)
{
    PartsList parts;
    parts.balls = balls;
    for (size_t k = 0; k < kStrutKindCount; ++k)
    {
        parts.struts[k] = static_cast<size_t>(std::ceil(kStrutsPerBall[k] * static_cast<double>(balls)));
        parts.strut_count += parts.struts[k];
    }
    return parts;
}

PartsList annealed_parts(size_t balls)
{
    // Struts per Z0 ball after a default 30 s run, median of the ten shared meshes (issue 38).
    constexpr std::array<double, kStrutKindCount> kAnnealedPerBall = {0.263, 0.882, 0.096, 0.185, 0.604,
                                                                      0.094, 0.062, 0.112, 0.045};
    PartsList parts;
    parts.balls = balls;
    for (size_t k = 0; k < kStrutKindCount; ++k)
    {
        parts.struts[k] = static_cast<size_t>(std::ceil(kAnnealedPerBall[k] * static_cast<double>(balls)));
        parts.strut_count += parts.struts[k];
    }
    return parts;
}

bool fits(const PartCounts& need, const PartCounts& have)
{
    for (size_t k = 0; k < need.size(); ++k)
        if (need[k] > have[k])
            return false;
    return true;
}

size_t balls_that_fit(const PartCounts& have, double margin)
{
    if (!(margin >= 0.0 && margin <= 0.9))
        throw InvalidInputError("the kit-fit margin must be between 0 and 0.9");
    // The mix is linear in the ball count, so the scarcest kind bounds it; ceil() in typical_parts
    // is undone by the check below.
    double most = static_cast<double>(have[kStrutKindCount]);
    for (size_t k = 0; k < kStrutKindCount; ++k)
        most = std::min(most, static_cast<double>(have[k]) / kStrutsPerBall[k]);
    size_t balls = static_cast<size_t>(std::floor(most * (1.0 - margin)));
    while (balls > 0 && !fits(part_counts(typical_parts(balls)), have))
        --balls;
    return balls;
}

size_t shrunk_ball_budget(const PartCounts& need, const PartCounts& have, size_t balls, double margin)
{
    double ratio = 1.0;
    for (size_t k = 0; k < need.size(); ++k)
        if (need[k] > 0)
            ratio = std::min(ratio, static_cast<double>(have[k]) / static_cast<double>(need[k]));
    const size_t next = static_cast<size_t>(std::floor(static_cast<double>(balls) * ratio * (1.0 - margin)));
    return balls == 0 ? 0 : std::min(next, balls - 1);
}

std::string fit_text(const PartCounts& need, const PartCounts& have)
{
    if (fits(need, have))
        return "fits your kits";
    PartCounts missing{};
    for (size_t k = 0; k < need.size(); ++k)
        missing[k] = need[k] > have[k] ? need[k] - have[k] : 0;
    return "missing with your kits: " + part_counts_text(missing);
}

PartsList parts_for_balls(const PartsList& z0_parts, size_t balls)
{
    if (balls <= z0_parts.balls || z0_parts.balls == 0)
        return z0_parts;
    PartsList out = z0_parts;
    const auto scaled = [&](size_t n) { return (n * balls + z0_parts.balls - 1) / z0_parts.balls; };
    out.balls = balls;
    out.strut_count = 0;
    for (size_t& n : out.struts)
    {
        n = scaled(n);
        out.strut_count += n;
    }
    const double f = static_cast<double>(balls) / static_cast<double>(z0_parts.balls);
    out.total_length_b0 *= f;
    out.total_length_mm *= f;
    return out;
}

} // namespace zomeify
