// One annealing thread (annealer.h explains the step). The only shared writes happen in the
// commit section (under commit_lock) or while every other worker is parked in the barrier.
#include <chrono>
#include <exception>
#include <functional>
#include <optional>
#include <shared_mutex>
#include <vector>

#include "core/anneal/engine/annealer_state.h"
#include "core/anneal/engine/change_region.h"
#include "core/anneal/engine/operator_draw.h"
#include "core/anneal/engine/seed_slabs.h"
#include "core/anneal/operators/mirrored.h"
#include "core/anneal/proposal.h"

namespace zomeify {

namespace {

// Counters are flushed to the shared atomics, the clock read and T recomputed once per batch.
constexpr uint64_t kBatch = 64;
// Draws of one proposal whose change overlaps its mirror image (mirrored.h).
constexpr int kMirrorDraws = 8;

// The time a commit waited for the commit lock (from `asked`) and held it (until destruction).
class SectionTimer
{
public:
    using Clock = std::chrono::steady_clock;
    SectionTimer(AnnealStats& totals, Clock::time_point asked) : totals_(totals), entered_(Clock::now())
    {
        totals_.commit_wait_seconds += std::chrono::duration<double>(entered_ - asked).count();
    }
    ~SectionTimer() { totals_.commit_hold_seconds += std::chrono::duration<double>(Clock::now() - entered_).count(); }
    SectionTimer(const SectionTimer&) = delete;
    SectionTimer& operator=(const SectionTimer&) = delete;

private:
    AnnealStats& totals_;
    Clock::time_point entered_;
};

class Worker
{
public:
    Worker(AnnealerState& state, int index, WorkerTotals& totals, const std::function<void()>& report)
        : s_(state), index_(index), totals_(totals.stats), report_(report),
          rng_(Rng::for_stream(state.options.seed, static_cast<uint64_t>(index))), shared_(state.options.threads > 1),
          by_proposals_(state.options.max_proposals > 0), operators_(state.options.operator_weights),
          fold_overs_(state.options.refuse_new_fold_overs ? FoldOvers::Refuse : FoldOvers::Count)
    {
        make_claims();
    }

    void run()
    {
        temperature_ = s_.schedule.temperature(0.0);
        uint64_t iteration = 0;
        while (!s_.stop.load(std::memory_order_acquire))
        {
            if (s_.barrier.requested())
            {
                pause();
                continue;
            }
            if (by_proposals_ && !shared_ && own_proposals_ >= s_.options.max_proposals)
            {
                s_.request_stop();
                break;
            }
            if (iteration++ % kBatch == 0 && !checkpoint())
                break;
            step();
        }
        flush();
    }

private:
    void make_claims()
    {
        claims_.emplace(shared_ ? s_.tags.get() : nullptr, static_cast<uint32_t>(index_ + 1));
        tags_generation_ = s_.tags_generation;
    }

    void pause()
    {
        flush();
        claims_->release_all();
        s_.barrier.arrive(s_.stop, [this] {
            std::lock_guard lock(s_.commit_lock);
            s_.make_room();
        });
        if (tags_generation_ != s_.tags_generation)
            make_claims();
        // Compaction renumbers the nodes.
        seeds_.clear();
        slab_epoch_ = kNoEpoch;
    }

    // The seeds of this thread's slab for the current epoch (seed_slabs.h). With one thread the
    // proposal count is exact at every checkpoint, so the epochs, and the run, are deterministic.
    void refresh_slab(uint64_t proposals_done)
    {
        const uint64_t epoch = proposals_done / s_.slabs.epoch_proposals;
        if (epoch == slab_epoch_ || !s_.options.sweep_slabs)
            return;
        std::unique_lock lock(s_.commit_lock, std::defer_lock);
        if (shared_)
            lock.lock(); // the mesh is read whole
        const int slab = slab_of_thread(epoch, index_, s_.options.threads, s_.slabs.slabs);
        seeds_ = seed_slab(s_.mesh, epoch, slab, s_.slabs.slabs);
        if (s_.options.region) // fixing one spot: only its nodes are seeds (the rest cannot change)
            std::erase_if(seeds_,
                          [this](MeshIndex v) { return !in_region(*s_.options.region, s_.mesh.position(Vertex(v))); });
        slab_epoch_ = epoch;
    }

    // A dead seed counts no proposal, so a slab whose nodes all went (a small model, a collapsed
    // part) would keep the epoch, and a proposal-budget run, from ever ending. After a streak of
    // dead seeds the slab's dead ones go; with none left the seeds are drawn among all nodes.
    // Only a streak triggers it, so runs that never see one draw exactly as before.
    void prune_dead_seeds()
    {
        std::shared_lock lock(s_.commit_lock, std::defer_lock);
        if (shared_)
            lock.lock(); // other nodes than the claimed seed are read
        std::erase_if(seeds_, [this](MeshIndex v) { return s_.mesh.is_deleted(Vertex(v)); });
        dead_in_row_ = 0;
    }

    // Budget, temperature and progress, once per batch. False when the budget is used.
    bool checkpoint()
    {
        flush();
        refresh_slab(s_.proposals.load(std::memory_order_relaxed));
        double fraction = 0.0;
        if (by_proposals_)
        {
            const uint64_t done = shared_ ? s_.proposals.load(std::memory_order_relaxed) : own_proposals_;
            if (done >= s_.options.max_proposals)
            {
                s_.request_stop();
                return false;
            }
            fraction = static_cast<double>(done) / static_cast<double>(s_.options.max_proposals);
        }
        else
        {
            const double elapsed = s_.clock.seconds();
            if (elapsed >= s_.options.seconds)
            {
                s_.request_stop();
                return false;
            }
            fraction = elapsed / s_.options.seconds;
        }
        temperature_ = s_.schedule.temperature(fraction);
        if (index_ == 0)
        {
            s_.temperature.store(temperature_, std::memory_order_relaxed);
            if (report_ && since_report_.seconds() >= s_.options.progress_interval)
            {
                report_();
                since_report_.restart();
            }
        }
        return true;
    }

    // Not inlined into run(): V8 moves a wasm function to its optimising compiler only for later
    // calls (no on-stack replacement), and run() is called once per thread, so whatever it
    // inlines would stay in the baseline tier for the whole run. step() is called per proposal.
    __attribute__((noinline)) void step()
    {
        const uint32_t published = s_.published_vertices.load(std::memory_order_acquire);
        if (published == 0)
            return;
        const Vertex seed(seeds_.empty() ? static_cast<MeshIndex>(rng_.below(published))
                                         : seeds_[rng_.below(seeds_.size())]);
        if (!claims_->take(seed))
        {
            ++totals_.busy_seeds;
            return;
        }
        if (s_.mesh.is_deleted(seed))
        {
            ++totals_.dead_seeds;
            claims_->release_all();
            if (++dead_in_row_ > 2 * seeds_.size() + kDeadSlack)
                prune_dead_seeds();
            return;
        }
        dead_in_row_ = 0;
        const OperatorKind kind = operators_.draw(rng_);
        OperatorCounts& counts = totals_.per_operator[static_cast<size_t>(kind)];
        ++counts.proposed;
        ++own_proposals_;
        ++unflushed_proposals_;
        for (int attempt = 0;; ++attempt)
        {
            if (!propose(kind, s_.mesh, seed, rng_, *claims_, proposal_))
            {
                ++totals_.rejections[static_cast<size_t>(proposal_.rejection)];
                claims_->release_all();
                return;
            }
            if (!s_.options.mirror)
                break;
            const Rejection r = mirror_proposal(s_.mesh, *s_.options.mirror, *claims_, proposal_);
            if (r == Rejection::None)
                break;
            ++totals_.rejections[static_cast<size_t>(r)];
            claims_->release_all();
            // Near the plane most random positions make a change that is not its own mirror image;
            // a few more draws at the same seed let balls on the plane move within it.
            if (r != Rejection::MirrorOverlap || attempt + 1 >= kMirrorDraws || !claims_->take(seed))
                return;
        }
        // No commit may add a face turned against the surface (no model gains a fold-over).
        EnergyDelta delta = s_.energy.simulate(s_.mesh, proposal_.change, fold_overs_);
        if (!delta.ok())
        {
            const Rejection why = delta.status == ChangeStatus::FoldOver ? Rejection::FoldOver : Rejection::Overflow;
            ++totals_.rejections[static_cast<size_t>(why)];
            claims_->release_all();
            return;
        }
        ++counts.valid;
        ++unflushed_valid_;
        // Drawn for every valid proposal, so the random stream does not depend on the outcome.
        const double u = rng_.uniform01();
        if (decide(delta, u) && commit(delta, u))
        {
            ++counts.accepted;
            ++unflushed_commits_;
        }
        claims_->release_all();
    }

    // E_surface's change, Metropolis and, for an accepted proposal, the clearance rule: they read
    // the sums and the model near the change, which claims do not cover, so under the commit lock
    // held shared: the threads decide at once while no commit runs. True when the proposal is
    // accepted and creates no clash (commit() checks whether a commit came in between).
    bool decide(EnergyDelta& delta, double u)
    {
        std::shared_lock lock(s_.commit_lock, std::defer_lock);
        if (shared_)
            lock.lock();
        decided_at_ = s_.commits_applied;
        return accepted_without_clash(delta, u);
    }

    bool accepted_without_clash(EnergyDelta& delta, double u)
    {
        s_.energy.add_surface_change(s_.mesh, proposal_.change, delta, surface_);
        if (!metropolis_accept(s_.energy.delta_energy(delta), temperature_, u))
            return false;
        if (s_.options.clearance)
            if (const ClashKind clash = s_.clearance.check(proposal_.change, clearance_); clash != ClashKind::None)
            {
                ++totals_.rejections[static_cast<size_t>(clash_rejection(clash))];
                return false;
            }
        return true;
    }

    bool commit(EnergyDelta delta, double u)
    {
        // Timed (three clock reads, tens of ns, for about one proposal in ten): the serial part.
        const auto asked = std::chrono::steady_clock::now();
        std::lock_guard lock(s_.commit_lock);
        const SectionTimer held(totals_, asked);
        // Another thread committed since this one decided: decide again, against the model now.
        if (s_.commits_applied != decided_at_)
        {
            ++totals_.redecisions;
            if (!accepted_without_clash(delta, u))
                return false;
        }
        const Rejection why = s_.apply_accepted(proposal_, delta, surface_, false);
        if (why == Rejection::None)
            return true;
        if (why == Rejection::Busy) // no room yet, or a position taken since propose()
            ++totals_.lost_races;
        else
            ++totals_.rejections[static_cast<size_t>(why)];
        return false;
    }

    void flush()
    {
        if (unflushed_proposals_)
            s_.proposals.fetch_add(unflushed_proposals_, std::memory_order_relaxed);
        if (unflushed_valid_)
            s_.valid_proposals.fetch_add(unflushed_valid_, std::memory_order_relaxed);
        if (unflushed_commits_)
            s_.commits.fetch_add(unflushed_commits_, std::memory_order_relaxed);
        unflushed_proposals_ = unflushed_valid_ = unflushed_commits_ = 0;
    }

    AnnealerState& s_;
    const int index_;
    AnnealStats& totals_;
    const std::function<void()>& report_;
    Rng rng_;
    const bool shared_, by_proposals_;
    const OperatorDraw operators_;
    const FoldOvers fold_overs_;
    std::optional<Claims> claims_;
    uint64_t tags_generation_ = 0;
    Proposal proposal_;
    SurfaceChange surface_;
    ClearanceIndex::Scratch clearance_;
    uint64_t decided_at_ = 0; // commits_applied when this thread last decided
    static constexpr uint64_t kNoEpoch = ~uint64_t{0};
    std::vector<MeshIndex> seeds_; // empty: draw among all nodes
    uint64_t slab_epoch_ = kNoEpoch;
    static constexpr size_t kDeadSlack = 64;
    size_t dead_in_row_ = 0;
    double temperature_ = 0.0;
    uint64_t own_proposals_ = 0;
    uint64_t unflushed_proposals_ = 0, unflushed_valid_ = 0, unflushed_commits_ = 0;
    Stopwatch since_report_;
};

} // namespace

void run_worker(AnnealerState& state, int index, WorkerTotals& totals, const std::function<void()>& report_progress)
{
    const auto fail = [&state](const char* what) {
        {
            std::lock_guard lock(state.commit_lock);
            if (state.error.empty())
                state.error = what;
        }
        state.request_stop();
    };
    try
    {
        Worker worker(state, index, totals, report_progress);
        worker.run();
    }
    catch (const std::exception& e)
    {
        fail(e.what());
    }
    catch (...)
    {
        fail("unknown exception in an annealing thread");
    }
    // Leave in every case, so the others are never left waiting at the barrier.
    state.barrier.leave([&state] {
        std::lock_guard lock(state.commit_lock);
        state.make_room();
    });
}

} // namespace zomeify
