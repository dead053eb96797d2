// The Annealer's setup, T0, thread management and results (the per-thread loop is in
// anneal_worker.cpp).
#include "core/anneal/engine/annealer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

#include "core/anneal/engine/annealer_state.h"
#include "core/anneal/engine/change_region.h"
#include "core/anneal/engine/fold_repair.h"
#include "core/anneal/operators/mirrored.h"
#include "core/anneal/proposal.h"
#include "core/base/errors.h"
#include "core/mesh/model_convert.h"

namespace zomeify {

namespace {

// Room reserved beyond the live elements: commits append and deletions are lazy, so the arrays
// fill up; a synchronized pause compacts them when the room is used.
size_t headroom(size_t live, size_t minimum) { return std::max(minimum, 4 * live); }

int default_threads()
{
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    return 1;
#else
    return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1U, 64U));
#endif
}

AnnealOptions resolve(AnnealOptions o, const ZomeMesh& mesh)
{
    if (mesh.n_vertices() == 0 || mesh.n_faces() == 0)
        throw InvalidInputError("the annealer needs a non-empty closed Zome model");
    if (o.max_proposals == 0 && !(std::isfinite(o.seconds) && o.seconds > 0.0))
        throw InvalidInputError("the annealing time must be a positive number of seconds");
    if (o.threads < 0 || o.threads > 64)
        throw InvalidInputError("threads must be between 0 (automatic) and 64");
    if (!(o.min_temperature > 0.0) || !std::isfinite(o.min_temperature))
        throw InvalidInputError("the minimum temperature must be positive");
    if (!(o.min_temperature_ratio >= 0.0 && o.min_temperature_ratio < 1.0))
        throw InvalidInputError("the minimum temperature ratio must be in [0, 1)");
    if (!(o.t0_spread_factor > 0.0) || !std::isfinite(o.t0_spread_factor))
        throw InvalidInputError("the T0 factor must be a positive number");
    if (!(o.initial_temperature >= 0.0) || !std::isfinite(o.initial_temperature))
        throw InvalidInputError("the initial temperature must be 0 (automatic) or positive");
    if (!(o.progress_interval > 0.0))
        o.progress_interval = 0.25;
    if (o.threads == 0)
        o.threads = default_threads();
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    o.threads = 1;
#endif
    if (o.target_nodes == 0)
        o.target_nodes = mesh.n_vertices();
    o.energy.target_nodes = o.target_nodes;
    return o;
}

// T0 = t0_spread_factor · stdev(ΔE) over random valid proposals on the starting mesh (paper §5.3). One
// thread, its own random stream: deterministic in the seed.
double estimate_t0(AnnealerState& s, int& valid)
{
    Rng rng = Rng::for_stream(s.options.seed, 0xFFFF);
    Claims claims; // unshared: every claim succeeds
    Proposal proposal;
    DeltaSpread spread;
    const auto samples = static_cast<uint64_t>(std::max(s.options.t0_samples, 0));
    const uint64_t attempts = 50 * samples;
    for (uint64_t i = 0; i < attempts && static_cast<uint64_t>(spread.count()) < samples; ++i)
    {
        const Vertex seed(static_cast<MeshIndex>(rng.below(s.mesh.vertices_size())));
        const auto kind = static_cast<OperatorKind>(rng.below(kOperatorKinds));
        if (s.mesh.is_deleted(seed) || !claims.take(seed))
            continue;
        if (propose(kind, s.mesh, seed, rng, claims, proposal) &&
            (!s.options.mirror || mirror_proposal(s.mesh, *s.options.mirror, claims, proposal) == Rejection::None))
        {
            // What the workers would consider.
            const FoldOvers fold_overs = s.options.refuse_new_fold_overs ? FoldOvers::Refuse : FoldOvers::Count;
            EnergyDelta delta = s.energy.simulate(s.mesh, proposal.change, fold_overs);
            if (delta.ok())
            {
                s.energy.add_surface_change(s.mesh, proposal.change, delta);
                spread.add(s.energy.delta_energy(delta));
            }
        }
        claims.release_all();
    }
    valid = spread.count();
    return s.options.t0_spread_factor * spread.stdev();
}

// The input surface's box in Zome units (where the model's grids are dense).
Box3 zome_box(const SurfaceContext& context)
{
    const ModelTransform& t = context.transform();
    const Vec3 translation(t.translation[0], t.translation[1], t.translation[2]);
    Box3 box;
    for (const Vec3& p : context.projector().mesh().positions)
        box.extend((p - translation) / t.scale);
    return box;
}

void add_counts(AnnealStats& into, const AnnealStats& from)
{
    for (int k = 0; k < kOperatorKinds; ++k)
    {
        into.per_operator[k].proposed += from.per_operator[k].proposed;
        into.per_operator[k].valid += from.per_operator[k].valid;
        into.per_operator[k].accepted += from.per_operator[k].accepted;
    }
    for (int r = 0; r < kRejectionKinds; ++r)
        into.rejections[r] += from.rejections[r];
    into.busy_seeds += from.busy_seeds;
    into.dead_seeds += from.dead_seeds;
    into.lost_races += from.lost_races;
    into.redecisions += from.redecisions;
    into.commit_hold_seconds += from.commit_hold_seconds;
    into.commit_wait_seconds += from.commit_wait_seconds;
}

} // namespace

AnnealerState::AnnealerState(ZomeMesh start, const SurfaceContext& ctx, const AnnealOptions& opts)
    : context(ctx), options(resolve(opts, start)), mesh(std::move(start)), energy(mesh, ctx, options.energy),
      coverage(ctx, mesh, options.coverage), clearance(dilated(zome_box(ctx), 8.0)), start_terms(energy.terms()),
      barrier(options.threads)
{
    uncovered_at_start = coverage.uncovered();
    clearance.reset(mesh);
    if (options.part_limits)
        parts.emplace(mesh);
    // A commit's new struts and faces take the slots its removed ones left, so a region's
    // elements stay together instead of being appended beside the other threads' (SurfaceMesh).
    mesh.set_slot_reuse(true);
    best_energy = start_terms.total;
}

void AnnealerState::make_room()
{
    mesh.garbage_collection();
    // Compaction renumbers the elements, which E_surface's points and the clearance grids name.
    energy.renumbered(mesh);
    clearance.reset(mesh);
    const size_t nv = mesh.n_vertices(), ne = mesh.n_edges(), nf = mesh.n_faces();
    const size_t vertex_room = nv + headroom(nv, 4096);
    mesh.reserve(vertex_room, ne + headroom(ne, 16384), nf + headroom(nf, 8192));
    if (!tags || tags->capacity() < vertex_room)
    {
        tags = std::make_unique<NodeTags>(vertex_room);
        ++tags_generation;
    }
    published_vertices.store(static_cast<uint32_t>(mesh.vertices_size()), std::memory_order_release);
}

namespace {

// What apply_proposal() appends (an upper bound for edges: faces create the struts they miss).
bool has_room(const ZomeMesh& mesh, const NodeTags& tags, const LocalChange& c) noexcept
{
    size_t edges = c.added_struts().size();
    for (const NewFace& f : c.added_faces())
        edges += f.size;
    return mesh.has_capacity_for(c.added_nodes().size(), edges, c.added_faces().size()) &&
           mesh.vertices_size() + c.added_nodes().size() <= tags.capacity();
}

// A new position may have been taken by another thread's commit since propose() looked it up
// (positions are global, not covered by claims).
bool positions_still_free(const ZomeMesh& mesh, const LocalChange& c) noexcept
{
    for (const ZVec& p : c.added_nodes())
    {
        const Vertex there = mesh.find_vertex(p);
        if (!there.is_valid())
            continue;
        bool leaving = false;
        for (const Vertex& r : c.removed_nodes())
            leaving = leaving || r == there;
        if (!leaving)
            return false;
    }
    return true;
}

} // namespace

Rejection clash_rejection(ClashKind clash) noexcept
{
    switch (clash)
    {
    case ClashKind::BallBall:
        return Rejection::BallsTooClose;
    case ClashKind::BallStrut:
        return Rejection::BallOnStrut;
    case ClashKind::StrutStrut:
        return Rejection::StrutsTooClose;
    default:
        return Rejection::StrutThroughFace;
    }
}

Rejection AnnealerState::apply_accepted(const Proposal& proposal, const EnergyDelta& delta,
                                        SurfaceChange& surface_change, bool check_clearance)
{
    const LocalChange& change = proposal.change;
    if (!has_room(mesh, *tags, change))
    {
        barrier.request();
        return Rejection::Busy;
    }
    if (!positions_still_free(mesh, change))
        return Rejection::Busy;
    if (options.clearance && check_clearance)
        if (const ClashKind clash = clearance.check(change); clash != ClashKind::None)
            return clash_rejection(clash);
    if (options.region && !region_allows(mesh, change, *options.region))
        return Rejection::OutsideRegion;
    PartTally::Counts part_delta{};
    if (parts)
    {
        part_delta = PartTally::change_of(mesh, change);
        if (!parts->allows(part_delta, *options.part_limits))
            return Rejection::OverKits;
    }
    // Last, because admitting updates the coverage counts as if the change were applied.
    if (!coverage.admit(mesh, change))
        return Rejection::Uncovered;
    added_faces.clear();
    clearance.forget(change);
    apply_proposal(mesh, proposal, &added_faces);
    const std::span<const Face> added(added_faces.begin(), added_faces.size());
    clearance.learn(mesh, change, added);
    energy.commit(delta, added, surface_change);
    if (parts)
        parts->apply(part_delta);
    ++commits_applied;
    published_vertices.store(static_cast<uint32_t>(mesh.vertices_size()), std::memory_order_release);
    if (!has_room_for_any())
        barrier.request();
    return Rejection::None;
}

bool AnnealerState::has_room_for_any() const
{
    constexpr size_t kNodes = LocalChange::kMaxNodes;
    constexpr size_t kEdges = LocalChange::kMaxStruts + 4 * LocalChange::kMaxFaces;
    return mesh.has_capacity_for(kNodes, kEdges, LocalChange::kMaxFaces) &&
           mesh.vertices_size() + kNodes <= tags->capacity();
}

double AnnealerState::fraction_now(uint64_t proposals_done) const noexcept
{
    if (!started.load())
        return 0.0;
    const double f = options.max_proposals > 0
                         ? static_cast<double>(proposals_done) / static_cast<double>(options.max_proposals)
                         : clock.seconds() / options.seconds;
    return std::clamp(f, 0.0, 1.0);
}

AnnealProgress AnnealerState::progress_locked() const
{
    AnnealProgress p;
    p.proposals = proposals.load(std::memory_order_relaxed);
    p.valid_proposals = valid_proposals.load(std::memory_order_relaxed);
    p.commits = commits.load(std::memory_order_relaxed);
    p.elapsed_seconds = started.load() ? clock.seconds() : 0.0;
    p.fraction = finished.load() ? 1.0 : fraction_now(p.proposals);
    p.temperature = temperature.load(std::memory_order_relaxed);
    p.energy = energy.terms();
    p.best_energy = best_energy;
    p.nodes = mesh.n_vertices();
    p.struts = mesh.n_edges();
    p.faces = mesh.n_faces();
    p.acceptance_rate =
        p.valid_proposals ? static_cast<double>(p.commits) / static_cast<double>(p.valid_proposals) : 0.0;
    p.finished = finished.load();
    return p;
}

struct Annealer::Impl
{
    Impl(ZomeMesh mesh, const SurfaceContext& context, const AnnealOptions& options)
        : state(std::move(mesh), context, options)
    {
    }
    AnnealerState state;
    ZomeModel best_model; // commit lock
};

Annealer::Annealer(ZomeMesh mesh, const SurfaceContext& context, const AnnealOptions& options)
    : impl_(std::make_unique<Impl>(std::move(mesh), context, options))
{
}

Annealer::Annealer(const ZomeModel& model, const SurfaceContext& context, const AnnealOptions& options)
    : Annealer(from_model(model), context, options)
{
}

Annealer::~Annealer() = default;

void Annealer::cancel() noexcept
{
    impl_->state.cancelled.store(true);
    impl_->state.request_stop();
}

AnnealProgress Annealer::progress() const
{
    std::lock_guard lock(impl_->state.commit_lock);
    return impl_->state.progress_locked();
}

ZomeModel Annealer::snapshot() const
{
    std::lock_guard lock(impl_->state.commit_lock);
    return to_model(impl_->state.mesh, impl_->state.context.transform());
}

const EnergyTerms& Annealer::start_energy() const noexcept { return impl_->state.start_terms; }

const AnnealOptions& Annealer::options() const noexcept { return impl_->state.options; }

AnnealResult Annealer::run(const ProgressCallback& progress)
{
    AnnealerState& s = impl_->state;
    if (s.started.exchange(true))
        throw std::logic_error("Annealer::run() called twice");
    const ModelTransform& transform = s.context.transform();

    const double t0 =
        s.options.initial_temperature > 0.0 ? s.options.initial_temperature : estimate_t0(s, s.t0_samples);
    const double t_min =
        s.options.min_temperature_ratio > 0.0 ? s.options.min_temperature_ratio * t0 : s.options.min_temperature;
    s.schedule = CoolingSchedule(t0, t_min);
    s.slabs = slab_plan(s.mesh.n_vertices(), s.options.threads);
    s.temperature.store(s.schedule.initial());
    {
        // progress() and snapshot() may already be called from other threads.
        std::lock_guard lock(s.commit_lock);
        s.make_room();
        impl_->best_model = to_model(s.mesh, transform);
        s.clock.restart();
    }

    // Progress (and the best-model sample) on worker 0, i.e. this thread.
    const std::function<void()> report = [this, &s, &progress, &transform] {
        AnnealProgress p;
        {
            std::lock_guard lock(s.commit_lock);
            p = s.progress_locked();
            if (p.energy.total < s.best_energy)
            {
                s.best_energy = p.energy.total;
                impl_->best_model = to_model(s.mesh, transform);
                p.best_energy = s.best_energy;
            }
        }
        if (progress)
            progress(p);
    };

    std::vector<WorkerTotals> totals(static_cast<size_t>(s.options.threads));
    std::vector<std::thread> threads;
    int running = 1;
    for (int i = 1; i < s.options.threads; ++i)
    {
        try
        {
            threads.emplace_back(run_worker, std::ref(s), i, std::ref(totals[static_cast<size_t>(i)]),
                                 std::function<void()>());
            ++running;
        }
        catch (const std::system_error&)
        {
            // No thread to be had (e.g. a wasm pool exhausted): fewer workers, same results' rules.
            s.barrier.leave([] {});
        }
    }
    run_worker(s, 0, totals[0], report);
    for (std::thread& t : threads)
        t.join();
    if (!s.error.empty())
        throw std::runtime_error("annealing failed: " + s.error);
    FoldRepairStats repair;
    if (s.options.repair_fold_overs && !s.options.mirror && !s.cancelled.load())
        repair = repair_fold_overs(s);
    s.finished.store(true);

    AnnealResult result;
    result.start = s.start_terms;
    result.model = to_model(s.mesh, transform);
    result.end = s.energy.terms();
    if (result.end.total <= s.best_energy)
    {
        result.best_model = result.model;
        result.best = result.end;
    }
    else
    {
        result.best_model = std::move(impl_->best_model);
        result.best = EnergyState(from_model(result.best_model), s.context, s.options.energy).terms();
    }
    AnnealStats& st = result.stats;
    for (const WorkerTotals& t : totals)
        add_counts(st, t.stats);
    st.wall_seconds = s.clock.seconds();
    st.threads = running;
    st.proposals = s.proposals.load();
    st.valid_proposals = s.valid_proposals.load();
    st.commits = s.commits.load();
    st.proposals_per_second = st.wall_seconds > 0 ? static_cast<double>(st.proposals) / st.wall_seconds : 0.0;
    st.commits_per_second = st.wall_seconds > 0 ? static_cast<double>(st.commits) / st.wall_seconds : 0.0;
    st.initial_temperature = s.schedule.initial();
    st.min_temperature = s.schedule.minimum();
    st.t0_valid_samples = s.t0_samples;
    st.cancelled = s.cancelled.load();
    st.garbage_collections = s.barrier.pauses();
    st.coverage_radius = s.coverage.enabled() ? s.options.coverage.radius : 0.0;
    st.coverage_samples = s.coverage.sample_count();
    st.uncovered_at_start = s.uncovered_at_start;
    st.uncovered_at_end = s.coverage.uncovered();
    st.fold_overs_before_repair = repair.before;
    st.fold_overs_after_repair = repair.after;
    st.repair_proposals = repair.proposals;
    st.repair_commits = repair.commits;
    st.energy_consistent = EnergyState(s.mesh, s.context, s.options.energy).sums() == s.energy.sums();
    if (progress)
    {
        std::lock_guard lock(s.commit_lock);
        AnnealProgress p = s.progress_locked();
        p.best_energy = result.best.total;
        progress(p);
    }
    return result;
}

EnergyTerms model_energy(const ZomeModel& model, const SurfaceContext& context, const EnergyOptions& options,
                         size_t target_nodes)
{
    const ZomeMesh mesh = from_model(model);
    EnergyOptions o = options;
    o.target_nodes = target_nodes ? target_nodes : mesh.n_vertices();
    return evaluate_energy(mesh, context, o);
}

} // namespace zomeify
