// ADDDIAG(f) (paper §3.2, §5.1): splits a quad (a, b, c, d) by the diagonal a–c into (a, b, c) and
// (c, d, a). The diagonal is MERGEVECTORS of the two quad edges a → b → c; a random one of the two
// diagonals is tried, the other if the first is no Zome vector.
#include "core/anneal/operators/operators.h"
#include "core/anneal/operators/region.h"
#include "core/mesh/circulators.h"
#include "core/zome/tables.h"

namespace zomeify::detail {
namespace {

// Whether the diagonal from `corner` merges the quad edges corner → corner+1 → corner+2.
bool diagonal_is_zome(const ZomeMesh& mesh, Face f, size_t corner) noexcept
{
    // Edge i of face_halfedges ends at corner i.
    int ids[4];
    size_t n = 0;
    for (Halfedge h : face_halfedges(mesh, f))
        ids[n++] = mesh.vector_id(h) == kNoZomeVector ? -1 : mesh.vector_id(h);
    const int a = ids[(corner + 1) % 4], b = ids[(corner + 2) % 4];
    return a >= 0 && b >= 0 && ZomeTables::get().merge(a, b) >= 0;
}

// The rest of ADDDIAG once the quad's region is loaded.
Rejection split_quad(const ZomeMesh& mesh, Face f, size_t corner, Claims& claims, Fill& fill,
                     LocalChange& change) noexcept
{
    if (fill.link_size() != 4)
        return Rejection::FaceSize;
    if (!diagonal_is_zome(mesh, f, corner))
        return Rejection::NoCandidate;
    const size_t a = corner % 2;
    fill.add_triangle(a, a + 1, a + 2);
    fill.add_triangle(a + 2, (a + 3) % 4, a);
    return complete_fill(mesh, fill, claims, change);
}

} // namespace

Rejection add_diag_at(const ZomeMesh& mesh, Face f, size_t corner, Claims& claims, Fill& fill,
                      LocalChange& change) noexcept
{
    if (const Rejection r = load_face_region(mesh, f, claims, fill, change); r != Rejection::None)
        return r;
    return split_quad(mesh, f, corner, claims, fill, change);
}

Rejection propose_add_diag(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                           LocalChange& change) noexcept
{
    const Face f = random_face(mesh, seed, rng, /*quads_only=*/true);
    if (!f.is_valid())
        return Rejection::NoCandidate;
    // Reading the edges of f needs its corners claimed: load the region first.
    if (const Rejection r = load_face_region(mesh, f, claims, fill, change); r != Rejection::None)
        return r;
    size_t corner = rng.below(2);
    if (!diagonal_is_zome(mesh, f, corner))
        corner = 1 - corner;
    return split_quad(mesh, f, corner, claims, fill, change);
}

} // namespace zomeify::detail
