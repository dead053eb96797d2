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

struct AreaFigures
{
    Vec3 centroid = Vec3::Zero();
    double area = 0.0;
};

AreaFigures area_figures(const TriangleMesh& mesh)
{
    AreaFigures f;
    for (const auto& t : mesh.triangles)
    {
        const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        const double area = 0.5 * (b - a).cross(c - a).norm();
        f.area += area;
        f.centroid += area * (a + b + c) / 3.0;
    }
    if (f.area > 0.0)
        f.centroid /= f.area;
    return f;
}

// The share of the surface's area within `band` of the plane: there a symmetric model can only have
// balls on the plane and struts across it, so the less of the shape lies there the better it fits.
double area_near(const TriangleMesh& mesh, const AxisPlane& plane, double band, double total)
{
    double near = 0.0;
    for (const auto& t : mesh.triangles)
    {
        const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        if (std::abs((a + b + c)[plane.axis] / 3.0 - plane.at) <= band)
            near += 0.5 * (b - a).cross(c - a).norm();
    }
    return total > 0.0 ? near / total : 0.0;
}

MirrorPlane along(const SurfaceProjector& surface, const AxisPlane& plane)
{
    Vec3 normal = Vec3::Zero();
    normal[plane.axis] = 1.0;
    return measure_mirror_plane(surface, normal, plane.at);
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
        c.measured = along(surface, *c.along);
    // A shape symmetric about several axis planes (a torus lying flat, the eight) is built on the one
    // through the least of its surface: a flat shape's middle plane holds its whole rim.
    const AreaFigures figures = area_figures(surface.mesh());
    const double band = 0.5 * b0;
    double least = c.along ? area_near(surface.mesh(), *c.along, band, figures.area) : 2.0;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (c.along && c.along->axis == axis)
            continue;
        const AxisPlane candidate{axis, figures.centroid[axis]};
        const double share = area_near(surface.mesh(), candidate, band, figures.area);
        if (share >= least)
            continue;
        const MirrorPlane m = along(surface, candidate);
        if (m.rms / b0 > kMirrorToleranceB0 || (c.along && m.rms / b0 > 2.0 * c.measured.rms / b0 + 0.01))
            continue;
        c.along = candidate;
        c.measured = m;
        least = share;
    }
    const double rms_b0 = c.measured.rms / b0;
    char text[400]; // planes print as `at + 0.0`: exactly -0 reads "0", never "-0"
    if (!c.along)
        std::snprintf(text, sizeof text,
                      "Not made mirror-symmetric: the shape's best mirror plane (normal %.2f, %.2f, %.2f) is not "
                      "perpendicular to an axis of the mesh.",
                      c.found.normal.x(), c.found.normal.y(), c.found.normal.z());
    else if (rms_b0 > kMirrorToleranceB0)
        std::snprintf(text, sizeof text,
                      "Not made mirror-symmetric: the shape's mirror image about %s = %.4g lies %.1f mm from it "
                      "(RMS; more than %.1f mm).",
                      axis_name(c.along->axis), c.along->at + 0.0, rms_b0 * kMmPerB0, kMirrorToleranceB0 * kMmPerB0);
    else
    {
        c.symmetric = true;
        std::snprintf(text, sizeof text,
                      "Mirror-symmetric about %s = %.4g: the shape's mirror image lies within %.1f mm of it (RMS "
                      "%.1f mm).",
                      axis_name(c.along->axis), c.along->at + 0.0, c.measured.max / b0 * kMmPerB0, rms_b0 * kMmPerB0);
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
