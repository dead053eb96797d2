#include "core/assembly/real_size.h"

#include <cmath>
#include <string>

#include "core/base/errors.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

constexpr double kMmPerB1 = kMmPerB0 * kPhi;
constexpr double kMinCells = 2, kMaxCells = 256; // pipeline.h's resolution bounds

std::string cm(double x) { return std::to_string(static_cast<long>(std::lround(x))); }

} // namespace

double built_size_cm(double extent_b0) { return (extent_b0 * kMmPerB0 + kBallDiameterMm) / 10.0; }

double b1_for_size_cm(double mesh_longest_side, double size_cm)
{
    if (!(mesh_longest_side > 0) || !std::isfinite(mesh_longest_side))
        throw InvalidInputError("the mesh has no extent to scale");
    // Centre-to-centre span in b1 lengths: the built side less one ball.
    const double cells = (size_cm * 10.0 - kBallDiameterMm) / kMmPerB1;
    const double lo = built_size_cm((kMinCells + 1) * kPhi), hi = built_size_cm(kMaxCells * kPhi);
    if (!std::isfinite(size_cm) || cells < kMinCells + 1 || cells > kMaxCells)
        throw InvalidInputError("--size-cm must be between " + cm(std::ceil(lo)) + " and " + cm(std::floor(hi)) +
                                " cm (3 to 256 b1 struts along the longest side)");
    // Z0's voxels cover the mesh conservatively: its balls span about one cell more than the mesh.
    return mesh_longest_side / (cells - 1.0);
}

} // namespace zomeify
