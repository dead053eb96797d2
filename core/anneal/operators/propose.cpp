// propose(): dispatch to the seven operators (proposal.h is the contract).
#include <algorithm>

#include "core/anneal/operators/operators.h"
#include "core/anneal/proposal.h"

namespace zomeify {

bool propose(OperatorKind kind, const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Proposal& out) noexcept
{
    using namespace detail;
    out.kind = kind;
    out.change.clear();
    // One fill per thread: no allocation and no clearing of the whole buffer per proposal.
    thread_local Fill fill;
    fill.clear();
    Rejection r = Rejection::NoCandidate;
    // is_deleted, not is_valid: is_valid reads the vertex count, which a committing thread may be
    // incrementing (a data race under ThreadSanitizer); the engine draws seeds below the count it
    // published, and a claimed node's deletion flag cannot change under us.
    if (claims.holds(seed) && !mesh.is_deleted(seed))
    {
        switch (kind)
        {
        case OperatorKind::InsNode:
            r = propose_ins_node(mesh, seed, rng, claims, fill, out.change);
            break;
        case OperatorKind::AddDiag:
            r = propose_add_diag(mesh, seed, rng, claims, fill, out.change);
            break;
        case OperatorKind::SplitStrut:
            r = propose_split_strut(mesh, seed, rng, claims, fill, out.change);
            break;
        case OperatorKind::RemDiag:
            r = propose_rem_diag(mesh, seed, rng, claims, fill, out.change);
            break;
        case OperatorKind::FlipDiag:
            r = propose_flip_diag(mesh, seed, rng, claims, fill, out.change);
            break;
        case OperatorKind::MovNode:
            r = propose_mov_node(mesh, seed, rng, claims, fill, out.change);
            break;
        case OperatorKind::RemNode:
            r = propose_rem_node(mesh, seed, rng, claims, fill, out.change);
            break;
        }
    }
    out.rejection = r;
    return r == Rejection::None;
}

bool new_positions_free(const ZomeMesh& mesh, const Proposal& proposal) noexcept
{
    const LocalChange& c = proposal.change;
    for (const ZVec& p : c.added_nodes())
    {
        const Vertex at = mesh.find_vertex(p);
        if (at.is_valid() &&
            std::find(c.removed_nodes().begin(), c.removed_nodes().end(), at) == c.removed_nodes().end())
            return false;
    }
    return true;
}

} // namespace zomeify
