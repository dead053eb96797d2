// Timing figures of the mesh operations the annealer's inner loop uses, printed as one JSON line.
// Was the GoogleTest case MeshPerf.ReportsFigures; a timing run belongs with the benchmarks. The checks are
// sanity checks only (exit 1 and a message on stderr when one fails).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>

#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/star.h"
#include "core/mesh/validate.h"
#include "core/zome/slots.h"
#include "tests/support/zome_fixtures.h"

using namespace zomeify;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

#define BENCH_CHECK(cond)                                                                                              \
    do                                                                                                                 \
    {                                                                                                                  \
        if (!(cond))                                                                                                   \
        {                                                                                                              \
            std::fprintf(stderr, "bench_mesh: check failed: %s\n", #cond);                                             \
            return 1;                                                                                                  \
        }                                                                                                              \
    } while (false)

} // namespace

int main()
{
    const ZomeModel shell = fixtures::cube_shell(40);
    auto t0 = Clock::now();
    ZomeMesh mesh = from_model(shell);
    const double build_s = seconds_since(t0);

    t0 = Clock::now();
    const ValidationReport r = validate(mesh);
    const double validate_s = seconds_since(t0);
    BENCH_CHECK(r.ok());

    // One-ring walks: slots and neighbour positions, as the energy and validity checks read them.
    // Best of three runs: the figures should not depend on what else the machine is doing.
    const int rounds = 20;
    uint64_t checksum = 0;
    double ring_ns = 1e300, lookup_ns = 1e300;
    size_t found = 0;
    for (int run = 0; run < 3; ++run)
    {
        t0 = Clock::now();
        for (int k = 0; k < rounds; ++k)
            for (Vertex v : vertices(mesh))
                for (Halfedge h : outgoing_halfedges(mesh, v))
                    checksum += static_cast<uint64_t>(mesh.slot(h)) +
                                static_cast<uint64_t>(mesh.position(mesh.to_vertex(h)).c[0]);
        ring_ns = std::min(ring_ns, seconds_since(t0) * 1e9 / (rounds * static_cast<double>(mesh.n_vertices())));
        t0 = Clock::now();
        found = 0;
        for (int k = 0; k < rounds; ++k)
            for (Vertex v : vertices(mesh))
                found += mesh.find_vertex(mesh.position(v)) == v;
        lookup_ns = std::min(lookup_ns, seconds_since(t0) * 1e9 / (rounds * static_cast<double>(mesh.n_vertices())));
    }
    BENCH_CHECK(checksum > 0u);
    BENCH_CHECK(found == rounds * mesh.n_vertices());

    std::vector<Vertex> link;
    t0 = Clock::now();
    size_t link_total = 0;
    for (Vertex v : vertices(mesh))
    {
        vertex_link(mesh, v, link);
        link_total += link.size();
    }
    const double link_ns = seconds_since(t0) * 1e9 / static_cast<double>(mesh.n_vertices());
    BENCH_CHECK(link_total > 0u);

    // Diagonal add + remove on the rhombohedral lattice (every face diagonal is a strut).
    ZomeMesh rh =
        from_model(fixtures::voxel_surface(fixtures::block_cells(12, 12, 12), fixtures::rhombohedral_basis()));
    std::mt19937 rng(5);
    // remove_edge keeps the lower-index face, so the original faces stay live throughout.
    const size_t n_quads = rh.faces_size();
    size_t pairs = 0;
    t0 = Clock::now();
    for (int k = 0; k < 200000; ++k)
    {
        const Face f(static_cast<MeshIndex>(rng() % n_quads));
        if (rh.is_deleted(f))
            continue;
        const Halfedge h = rh.halfedge(f);
        const Vertex a = rh.to_vertex(h), b = rh.to_vertex(rh.next(rh.next(h)));
        if (!rh.is_split_ok(f, a, b))
            continue;
        const Halfedge d = rh.split_face(f, a, b);
        rh.remove_edge(SurfaceMesh::edge(d));
        ++pairs;
    }
    const size_t grown_edges = rh.edges_size();
    const double diag_ns = seconds_since(t0) * 1e9 / static_cast<double>(pairs);
    t0 = Clock::now();
    rh.garbage_collection();
    const double gc_s = seconds_since(t0);
    BENCH_CHECK(validate(rh).ok());

    // Remove a face and add it back (the clear-and-refill cycle of every operator).
    size_t refills = 0;
    std::vector<Vertex> corners;
    t0 = Clock::now();
    for (int k = 0; k < 100000; ++k)
    {
        const Face f(static_cast<MeshIndex>(rng() % rh.faces_size()));
        if (rh.is_deleted(f))
            continue;
        corners.clear();
        for (Vertex v : face_vertices(rh, f))
            corners.push_back(v);
        rh.remove_face(f);
        rh.add_face(corners);
        ++refills;
    }
    const double refill_ns = seconds_since(t0) * 1e9 / static_cast<double>(refills);
    BENCH_CHECK(validate(rh).ok());

    std::printf("{\"bench\":\"mesh\",\"nodes\":%zu,\"from_model_ms\":%.2f,\"validate_ms\":%.2f,"
                "\"one_ring_ns\":%.1f,\"position_lookup_ns\":%.1f,\"vertex_link_ns\":%.1f,"
                "\"diagonal_split_merge_ns\":%.1f,\"face_remove_add_ns\":%.1f,\"gc_ms\":%.2f,\"gc_nodes\":%zu,\"gc_"
                "edges_before\":%zu,\"pairs\":%zu}\n",
                mesh.n_vertices(), build_s * 1e3, validate_s * 1e3, ring_ns, lookup_ns, link_ns, diag_ns, refill_ns,
                gc_s * 1e3, rh.n_vertices(), grown_edges, pairs);
    return 0;
}
