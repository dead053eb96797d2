#include "tests/fuzz/fuzz_mesh.h"

#include <span>

#include "core/base/errors.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "tests/fuzz/fuzz_target.h"

namespace zomeify::fuzz {

namespace {

// Above this the repair path costs more per execution than it is worth: the readers are the target,
// and a soup this size already reaches every branch of weld, triangulate and the topology analysis.
constexpr size_t max_repaired_elements = 4096;

void repair(const PolygonSoup& soup)
{
    size_t corners = 0;
    for (const auto& polygon : soup.polygons)
        corners += polygon.size();
    if (soup.positions.size() > max_repaired_elements || corners > 4 * max_repaired_elements)
        return;
    const SurfaceReport report = diagnose(soup);
    ZOME_FUZZ_CHECK(report.input_vertices == soup.positions.size(), "diagnose counts the input vertices");
    ZOME_FUZZ_CHECK(report.input_faces == soup.polygons.size(), "diagnose counts the input faces");
    ZOME_FUZZ_CHECK(report.ok() == report.problem_summary().empty(), "ok() agrees with the summary");
    try
    {
        const PreparedSurface prepared = prepare_surface(soup);
        ZOME_FUZZ_CHECK(report.ok(), "prepare_surface accepts only what diagnose accepts");
        ZOME_FUZZ_CHECK(prepared.report.closed && prepared.report.manifold,
                        "a prepared surface is closed and manifold");
        const size_t vertices = prepared.mesh.positions.size();
        for (const auto& triangle : prepared.mesh.triangles)
            for (uint32_t v : triangle)
                ZOME_FUZZ_CHECK(v < vertices, "prepared triangles index existing vertices");
    }
    catch (const InvalidInputError&)
    {
        ZOME_FUZZ_CHECK(!report.ok(), "prepare_surface refuses only what diagnose refuses");
    }
}

} // namespace

int fuzz_mesh_input(const uint8_t* data, size_t size, const char* file_name)
{
    PolygonSoup soup;
    try
    {
        soup = read_mesh_buffer(std::span<const uint8_t>(data, size), file_name);
    }
    catch (const InvalidInputError&)
    {
        return 0;
    }
    repair(soup);
    return 0;
}

} // namespace zomeify::fuzz
