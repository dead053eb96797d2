// The paper's operator names and the rejection reasons, for statistics and reports.
#include "core/anneal/proposal.h"

namespace zomeify {

std::string_view operator_name(OperatorKind kind) noexcept
{
    switch (kind)
    {
    case OperatorKind::InsNode:
        return "INSNODE";
    case OperatorKind::AddDiag:
        return "ADDDIAG";
    case OperatorKind::SplitStrut:
        return "SPLITSTRUT";
    case OperatorKind::RemDiag:
        return "REMDIAG";
    case OperatorKind::FlipDiag:
        return "FLIPDIAG";
    case OperatorKind::MovNode:
        return "MOVNODE";
    case OperatorKind::RemNode:
        return "REMNODE";
    }
    return "?";
}

std::string_view rejection_name(Rejection r) noexcept
{
    switch (r)
    {
    case Rejection::None:
        return "none";
    case Rejection::Busy:
        return "busy";
    case Rejection::NoCandidate:
        return "no candidate";
    case Rejection::FaceSize:
        return "face size";
    case Rejection::Valence:
        return "valence";
    case Rejection::Occupied:
        return "occupied";
    case Rejection::SlotConflict:
        return "slot conflict";
    case Rejection::DoubleStrut:
        return "double strut";
    case Rejection::LinkTwice:
        return "link node twice";
    case Rejection::Topology:
        return "topology";
    case Rejection::FoldedQuad:
        return "folded quad";
    case Rejection::FoldOver:
        return "fold-over";
    case Rejection::Uncovered:
        return "uncovers surface";
    case Rejection::BallsTooClose:
        return "balls too close";
    case Rejection::BallOnStrut:
        return "ball on a strut";
    case Rejection::StrutsTooClose:
        return "struts too close";
    case Rejection::StrutThroughFace:
        return "strut through a face";
    case Rejection::OverKits:
        return "over the kits";
    case Rejection::OutsideRegion:
        return "outside the region";
    case Rejection::MirrorOverlap:
        return "overlaps its mirror image";
    case Rejection::Overflow:
        return "overflow";
    }
    return "?";
}

} // namespace zomeify
