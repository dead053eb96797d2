#include "core/pipeline/mirror_choice.h"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "core/zome/real_sizes.h"

namespace zomeify {
namespace {

const char* axis_name(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

std::optional<AxisPlane> along_axis(const MirrorPlane& plane)
{
    int axis = 0;
    plane.normal.cwiseAbs().maxCoeff(&axis);
    const double cos_limit = std::cos(kMirrorAxisDegrees * 3.14159265358979323846 / 180.0);
    if (std::abs(plane.normal[axis]) < cos_limit)
        return std::nullopt;
    return AxisPlane{axis, plane.normal[axis] > 0.0 ? plane.offset : -plane.offset};
}

} // namespace

MirrorChoice choose_mirror(const SurfaceProjector& surface, double b0)
{
    MirrorChoice c;
    c.mode = MirrorMode::Auto;
    c.b0 = b0;
    c.found = find_mirror_plane(surface);
    c.along = along_axis(c.found);
    c.measured = c.found;
    if (c.along)
    {
        Vec3 normal = Vec3::Zero();
        normal[c.along->axis] = 1.0;
        c.measured = measure_mirror_plane(surface, normal, c.along->at);
    }
    const double rms_b0 = c.measured.rms / b0;
    char text[400];
    if (!c.along)
        std::snprintf(text, sizeof text,
                      "Not made mirror-symmetric: the shape's best mirror plane (normal %.2f, %.2f, %.2f) is not "
                      "perpendicular to an axis of the mesh.",
                      c.found.normal.x(), c.found.normal.y(), c.found.normal.z());
    else if (rms_b0 > kMirrorToleranceB0)
        std::snprintf(text, sizeof text,
                      "Not made mirror-symmetric: the shape's mirror image about %s = %.4g lies %.1f mm from it "
                      "(RMS; more than %.1f mm).",
                      axis_name(c.along->axis), c.along->at, rms_b0 * kMmPerB0, kMirrorToleranceB0 * kMmPerB0);
    else
    {
        c.symmetric = true;
        std::snprintf(text, sizeof text,
                      "Mirror-symmetric about %s = %.4g: the shape's mirror image lies within %.1f mm of it (RMS "
                      "%.1f mm).",
                      axis_name(c.along->axis), c.along->at, c.measured.max / b0 * kMmPerB0, rms_b0 * kMmPerB0);
    }
    c.message = text;
    return c;
}

AxisPlane mesh_plane(const LatticeMirror& mirror, const ModelTransform& transform)
{
    return {mirror.axis, mirror.coordinate() * transform.scale + transform.translation[mirror.axis]};
}

std::string mirror_choice_json(const MirrorChoice& c)
{
    nlohmann::json j = {{"mode", c.mode == MirrorMode::Auto ? "auto" : "off"}, {"message", c.message}};
    if (c.mode == MirrorMode::Auto)
    {
        const double mm = c.b0 > 0.0 ? kMmPerB0 / c.b0 : 0.0;
        j["normal"] = {c.measured.normal.x(), c.measured.normal.y(), c.measured.normal.z()};
        j["offset"] = c.measured.offset;
        j["rms_b0"] = c.b0 > 0.0 ? c.measured.rms / c.b0 : 0.0;
        j["rms_mm"] = c.measured.rms * mm;
        j["max_mm"] = c.measured.max * mm;
        j["symmetric"] = c.symmetric;
        j["used"] = c.used.has_value();
        if (c.along)
        {
            j["axis"] = axis_name(c.along->axis);
            j["at"] = c.along->at;
        }
    }
    return j.dump();
}

} // namespace zomeify
