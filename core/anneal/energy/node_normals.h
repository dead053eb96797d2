#pragma once
//! \file node_normals.h
//! NodeNormals: n(π(p)) for the node positions of one local computation, remembered so that a node
//! shared by several changed faces (up to one lookup per corner) is projected once. Local scratch of
//! one thread, never shared; the values are those of SurfaceContext, so results do not depend on
//! whether a normal was remembered.

#include <utility>

#include "core/anneal/energy/surface_context.h"
#include "core/anneal/fixed_list.h"

namespace zomeify {

class NodeNormals
{
public:
    explicit NodeNormals(const SurfaceContext& context) noexcept : context_(context) {}

    //! The surface normal at π(p) for a node at p.
    Vec3 at(const ZVec& p) noexcept
    {
        for (const auto& [q, n] : known_)
        {
            if (q == p)
            {
                return n;
            }
        }
        const Vec3 n = context_.node_normal(p);
        remember(p, n);
        return n;
    }
    //! Records a normal the caller already has (from a node's distance sample).
    void remember(const ZVec& p, const Vec3& n) noexcept { known_.push_back({p, n}); }
    //! Forgets everything (a full list simply stops remembering).
    void clear() noexcept { known_.clear(); }

    const SurfaceContext& context() const noexcept { return context_; }

private:
    const SurfaceContext& context_;
    FixedList<std::pair<ZVec, Vec3>, 48> known_;
};

} // namespace zomeify
