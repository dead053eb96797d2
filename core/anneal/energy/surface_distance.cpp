#include "core/anneal/energy/surface_distance.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"

namespace zomeify {
namespace {

// A box's distance is a lower bound of its face's, but both are rounded: a face is skipped only
// when its box is farther than the best distance by more than any rounding (b0²).
constexpr double kSlack = 1e-9;
// Cells of the grids (b0): about a face across.
constexpr double kFaceCell = 1.0;
constexpr double kSampleCell = 1.0;

FaceShape mesh_face_shape(const ZomeMesh& mesh, Face f)
{
    std::array<ZVec, 4> corners;
    size_t n = 0;
    for (Vertex v : face_vertices(mesh, f))
    {
        if (n == corners.size())
            return {}; // not a triangle or quad: no shape (validate() refuses such meshes)
        corners[n++] = mesh.position(v);
    }
    return face_shape(std::span<const ZVec>(corners.data(), n));
}

} // namespace

SurfaceDistance::SurfaceDistance(const SurfaceContext& context, const EnergyOptions& options)
    : enabled_(options.w_surface != 0.0), options_(options), cap2_(options.surface_cap * options.surface_cap)
{
    if (!(options.surface_spacing > 0.0) || !std::isfinite(options.surface_spacing))
        throw InvalidInputError("the surface sample spacing must be a positive number of b0");
    if (!(options.surface_cap > 0.0) || !std::isfinite(options.surface_cap))
        throw InvalidInputError("the surface distance cap must be a positive number of b0");
    if (!enabled_)
        return;
    grid_ = SampleGrid(surface_sample_points(context, options.surface_spacing), kSampleCell);
    Box3 domain;
    for (const Vec3& p : grid_.points())
        domain.extend(p);
    faces_ = ElementGrid<FaceShape>(dilated(domain, options.surface_cap + 4.0), kFaceCell);
    d2_.assign(grid_.size(), cap2_);
    bound_.assign(grid_.size(), cap2_);
    owner_.assign(grid_.size(), kNone);
    next_owned_.assign(grid_.size(), kNone);
    previous_owned_.assign(grid_.size(), kNone);
    cell_d2_.assign(grid_.cell_count(), cap2_);
    cell_bound_.assign(grid_.cell_count(), cap2_);
}

EnergyFixed SurfaceDistance::value(double d2) const noexcept
{
    d2 = std::min(d2, cap2_);
    return quantize(d2 * (1.0 + forbidden_zone(std::sqrt(d2), options_.surface_zone)));
}

void SurfaceDistance::next_mark(SurfaceChange& c) noexcept
{
    if (++c.mark_ == 0) // wrapped: old marks could match again
    {
        std::fill(c.removed_mark_.begin(), c.removed_mark_.end(), 0U);
        std::fill(c.updated_mark_.begin(), c.updated_mark_.end(), 0U);
        c.mark_ = 1;
    }
}

void SurfaceDistance::link(uint32_t point, uint32_t face)
{
    owner_[point] = face;
    previous_owned_[point] = kNone;
    next_owned_[point] = kNone;
    if (face == kNone)
        return;
    if (face >= first_owned_.size())
        first_owned_.resize(std::max<size_t>(face + 1, 2 * first_owned_.size()), kNone);
    const uint32_t head = first_owned_[face];
    next_owned_[point] = head;
    if (head != kNone)
        previous_owned_[head] = point;
    first_owned_[face] = point;
}

void SurfaceDistance::unlink(uint32_t point)
{
    const uint32_t face = owner_[point];
    if (face == kNone)
        return;
    const uint32_t prev = previous_owned_[point], next = next_owned_[point];
    if (prev != kNone)
        next_owned_[prev] = next;
    else
        first_owned_[face] = next;
    if (next != kNone)
        previous_owned_[next] = prev;
    owner_[point] = kNone;
}

void SurfaceDistance::refresh_cell_bound(uint32_t cell)
{
    double d2 = 0.0, bound = 0.0;
    for (uint32_t i = grid_.begin(cell); i < grid_.end(cell); ++i)
    {
        d2 = std::max(d2, d2_[i]);
        bound = std::max(bound, bound_[i]);
    }
    cell_d2_[cell] = d2;
    cell_bound_[cell] = bound;
}

void SurfaceDistance::search_grid(const Vec3& p, Nearest& n, SurfaceChange& c) const
{
    // The box reaches as far as the best so far: faces outside it are farther than that, so it
    // also bounds the others.
    const double reach = n.best;
    Box3 box;
    box.extend(p);
    faces_.for_each_near(dilated(box, std::sqrt(reach) + kSlack), c.visits_,
                         [&](uint32_t face, const FaceShape& shape) {
                             if (!removed(c, face))
                                 n.offer(face_distance_squared_below(p, shape, n.best), face, false);
                         });
    n.second = std::min(n.second, reach);
}

void SurfaceDistance::search_added(const Vec3& p, Nearest& n, const SurfaceChange& c) noexcept
{
    for (size_t k = 0; k < c.added_.size(); ++k)
        n.offer(face_distance_squared_below(p, c.added_[k], n.best), static_cast<uint32_t>(k), true);
}

void SurfaceDistance::reset(const ZomeMesh& mesh)
{
    sum_ = 0;
    ++version_;
    next_mark(own_); // nothing counts as removed
    if (!enabled_)
        return;
    faces_.clear();
    std::fill(first_owned_.begin(), first_owned_.end(), kNone);
    for (Face f : faces(mesh))
        faces_.insert(f.idx(), mesh_face_shape(mesh, f));
    const std::vector<Vec3>& points = grid_.points();
    for (uint32_t i = 0; i < points.size(); ++i)
    {
        Nearest n{cap2_, cap2_, kNone, false};
        search_grid(points[i], n, own_);
        d2_[i] = n.best;
        bound_[i] = n.second;
        link(i, n.owner);
        sum_ += value(n.best);
    }
    for (uint32_t c = 0; c < grid_.cell_count(); ++c)
        refresh_cell_bound(c);
}

void SurfaceDistance::record(uint32_t point, const Nearest& n, SurfaceChange& c) const
{
    c.updates_.push_back({point, n.owner, n.owner_added, n.best, n.second});
    c.updated_mark_[point] = c.mark_;
    c.delta_ += value(n.best) - value(d2_[point]);
}

EnergyAccumulator SurfaceDistance::simulate(const ZomeMesh& mesh, const LocalChange& change, SurfaceChange& c) const
{
    c.updates_.clear();
    c.added_.clear();
    c.removed_faces_.clear();
    c.added_box_ = Box3();
    c.delta_ = 0;
    c.version_ = version_;
    if (!enabled_)
        return 0;
    next_mark(c);
    if (c.removed_mark_.size() < mesh.faces_size())
        c.removed_mark_.resize(mesh.faces_size(), 0);
    if (c.updated_mark_.size() < grid_.size())
        c.updated_mark_.resize(grid_.size(), 0);
    for (Face f : change.removed_faces())
    {
        c.removed_faces_.push_back(f.idx());
        c.removed_mark_[f.idx()] = c.mark_;
    }
    for (const NewFace& f : change.added_faces())
    {
        c.added_.push_back(face_shape(f.view()));
        c.added_box_.extend(c.added_[c.added_.size() - 1].box);
    }

    // Points whose nearest face goes. Every face that stays is at least bound_ away: when an added
    // face is nearer, it is the nearest; otherwise the grid has the answer.
    const std::vector<Vec3>& points = grid_.points();
    for (uint32_t face : c.removed_faces_)
        for (uint32_t i = face < first_owned_.size() ? first_owned_[face] : kNone; i != kNone; i = next_owned_[i])
        {
            Nearest n{cap2_, cap2_, kNone, false};
            search_added(points[i], n, c);
            if (n.best <= bound_[i])
                n.second = std::min(n.second, bound_[i]);
            else
                search_grid(points[i], n, c);
            record(i, n, c);
        }

    // Points an added face comes closer to: only in cells whose farthest point can reach it.
    if (c.added_box_.empty())
        return c.delta_;
    const Box3& added_box = c.added_box_;
    grid_.for_each_cell_near(dilated(added_box, options_.surface_cap), [&](size_t cell, const Box3& cell_box) {
        const Vec3 gap = (added_box.min - cell_box.max).cwiseMax(cell_box.min - added_box.max).cwiseMax(0.0);
        if (gap.squaredNorm() > cell_d2_[cell] + kSlack)
            return;
        for (uint32_t i = grid_.begin(cell); i < grid_.end(cell); ++i)
        {
            const Vec3& p = points[i];
            if (c.updated_mark_[i] == c.mark_ || added_box.distance_squared(p) > d2_[i] + kSlack)
                continue; // lost (done above), or out of reach
            // The old owner stays, now one of the others.
            Nearest n{d2_[i], bound_[i], owner_[i], false};
            search_added(p, n, c);
            if (n.owner_added)
                record(i, n, c);
        }
    });
    return c.delta_;
}

void SurfaceDistance::lower_bounds_near_added(const SurfaceChange& c)
{
    const std::vector<Vec3>& points = grid_.points();
    const Box3& added_box = c.added_box_;
    grid_.for_each_cell_near(dilated(added_box, options_.surface_cap), [&](size_t cell, const Box3& cell_box) {
        const Vec3 gap = (added_box.min - cell_box.max).cwiseMax(cell_box.min - added_box.max).cwiseMax(0.0);
        if (gap.squaredNorm() > cell_bound_[cell] + kSlack)
            return;
        bool lowered = false;
        for (uint32_t i = grid_.begin(cell); i < grid_.end(cell); ++i)
        {
            // A bound only has to stay below the truth: the added faces' common box is enough, and
            // costs a fraction of their distances (a point whose bound is too low is searched anew).
            const double d = added_box.distance_squared(points[i]);
            if (d < bound_[i] && c.updated_mark_[i] != c.mark_)
            {
                bound_[i] = d;
                lowered = true;
            }
        }
        if (lowered)
            refresh_cell_bound(static_cast<uint32_t>(cell));
    });
}

void SurfaceDistance::commit(SurfaceChange& c, std::span<const Face> added)
{
    if (!enabled_)
        return;
    for (uint32_t f : c.removed_faces_)
        faces_.erase(f);
    for (size_t k = 0; k < c.added_.size() && k < added.size(); ++k)
        faces_.insert(added[k].idx(), c.added_[k]);
    touched_cells_.clear();
    for (const SurfaceChange::Update& u : c.updates_)
    {
        unlink(u.point);
        d2_[u.point] = u.d2;
        bound_[u.point] = u.bound;
        link(u.point, u.owner_added ? added[u.owner].idx() : u.owner);
        const uint32_t cell = grid_.cell_of_point(u.point);
        if (std::find(touched_cells_.begin(), touched_cells_.end(), cell) == touched_cells_.end())
            touched_cells_.push_back(cell);
    }
    for (uint32_t cell : touched_cells_)
        refresh_cell_bound(cell);
    if (!c.added_box_.empty())
        lower_bounds_near_added(c);
    sum_ += c.delta_;
    ++version_;
    c.updates_.clear();
    c.removed_faces_.clear();
    c.added_.clear();
    c.delta_ = 0;
}

SurfaceSums evaluate_surface_distance(const ZomeMesh& mesh, const SurfaceContext& context, const EnergyOptions& options)
{
    if (options.w_surface == 0.0)
        return {};
    SurfaceDistance term(context, options);
    term.reset(mesh);
    return {term.sum(), static_cast<int64_t>(term.sample_count())};
}

} // namespace zomeify
