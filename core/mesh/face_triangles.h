#pragma once
//! \file face_triangles.h
//! The triangles by which a face of the model is measured (its distance to a point, whether a strut
//! crosses it, the fidelity score). A quad of Zome struts need not be planar, so its surface is
//! defined by one of its diagonals; which one must not depend on the corner a caller starts from,
//! or the same face would give different distances when counted from the mesh and from an
//! operator's description. Rule: the shorter diagonal (exact lengths; the flatter, more compact
//! split of a skew quad, and the one a person would stretch a panel over), and for equal ones the
//! diagonal through the smallest corner (ZVec order). The corners are rotated so that the
//! diagonal's smaller end comes first, then fanned: (c0, c1, c2) and (c0, c2, c3); a triangle
//! starts at its smallest corner. Orientation is kept (counter-clockwise seen from outside), and
//! every caller gets the same corners in the same order, so floating-point results are
//! bit-identical too.

#include <array>
#include <cstddef>
#include <span>

#include "core/zome/zvec.h"

namespace zomeify {

struct FaceTriangles
{
    std::array<std::array<ZVec, 3>, 2> triangles{};
    int count = 0; //!< 1 for a triangle, 2 for a quad, 0 for anything else
};

//! The canonical triangles of a face with 3 or 4 corners (counter-clockwise seen from outside).
inline FaceTriangles face_triangles(std::span<const ZVec> corners) noexcept
{
    FaceTriangles out;
    const size_t n = corners.size();
    if (n != 3 && n != 4)
        return out;
    size_t first = 0;
    for (size_t i = 1; i < n; ++i)
        if (corners[i] < corners[first])
            first = i;
    if (n == 4)
    {
        // Diagonal 0–2 or 1–3 (by index): keep the shorter, then start at its smaller end.
        const int order = compare(norm4(corners[2] - corners[0]), norm4(corners[3] - corners[1]));
        const size_t d = order < 0 ? 0 : order > 0 ? 1 : first % 2;
        first = corners[d + 2] < corners[d] ? d + 2 : d;
    }
    const auto at = [&](size_t k) -> const ZVec& { return corners[(first + k) % n]; };
    out.triangles[0] = {at(0), at(1), at(2)};
    if (n == 4)
        out.triangles[1] = {at(0), at(2), at(3)};
    out.count = static_cast<int>(n) - 2;
    return out;
}

} // namespace zomeify
