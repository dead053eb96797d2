#pragma once
//! \file pause_barrier.h
//! PauseBarrier: the synchronized state of paper §5.2 ("garbage collection ... only in a
//! synchronized state by a single thread while the others are idle"). A thread that finds the
//! mesh short of room raises the request; every worker, between two proposals (holding no
//! claims), arrives; the last to arrive runs the maintenance alone, then all resume. Stopping
//! releases waiting threads, and a thread that leaves no longer counts, so nobody waits forever.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>

namespace zomeify {

class PauseBarrier
{
public:
    explicit PauseBarrier(int workers) : active_(workers) {}

    void request() noexcept { requested_.store(true, std::memory_order_release); }
    bool requested() const noexcept { return requested_.load(std::memory_order_acquire); }

    //! Called by a worker that saw requested(). The last one to arrive calls maintain() (with
    //! every other worker parked here), then all return. Returns early if `stop` becomes true.
    template <class F>
    void arrive(const std::atomic<bool>& stop, F&& maintain)
    {
        std::unique_lock lock(mutex_);
        if (!requested_.load(std::memory_order_acquire))
            return; // another worker already ran the maintenance
        if (++arrived_ == active_)
        {
            run_maintenance(maintain);
            return;
        }
        const uint64_t generation = generation_;
        cv_.wait(lock, [&] { return generation_ != generation || stop.load(std::memory_order_acquire); });
        if (generation_ == generation)
            --arrived_;
    }
    //! A worker leaves for good (after stop). Completes a pending pause if it was the last one
    //! missing, so the others are released.
    template <class F>
    void leave(F&& maintain)
    {
        std::unique_lock lock(mutex_);
        --active_;
        if (arrived_ > 0 && arrived_ == active_)
            run_maintenance(maintain);
        cv_.notify_all();
    }
    //! Wakes every waiting worker (call after setting the stop flag).
    void wake_all()
    {
        std::lock_guard lock(mutex_);
        cv_.notify_all();
    }
    uint64_t pauses() const
    {
        std::lock_guard lock(mutex_);
        return generation_;
    }

private:
    template <class F>
    void run_maintenance(F& maintain)
    {
        maintain();
        requested_.store(false, std::memory_order_release);
        arrived_ = 0;
        ++generation_;
        cv_.notify_all();
    }

    mutable std::mutex mutex_;
    std::condition_variable cv_;
    std::atomic<bool> requested_{false};
    int active_;
    int arrived_ = 0;
    uint64_t generation_ = 0;
};

} // namespace zomeify
