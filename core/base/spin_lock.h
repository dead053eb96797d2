#pragma once
//! \file spin_lock.h
//! Locks for short critical sections. Unlike a mutex they never enter the kernel and unlock is a
//! plain store, so an uncontended lock/unlock pair costs one atomic exchange, and a contended one
//! no futex wake-up (a std::mutex for the annealer's commits spent ~5% of two threads' time in
//! the kernel, tests/bench/README.md). Waiters spin on a load (no writes while the line is held)
//! and yield to the scheduler after `SpinsBeforeYield` rounds, so a holder preempted on an
//! oversubscribed machine is not starved. In wasm the yield does nothing (Emscripten's sched_yield
//! only runs the thread's queued calls), so there waiters spin. Sleeping instead (a 50 µs futex
//! wait, 2026-12-07) was tried under node, 10 s runs of the bunny: after 2048 rounds two threads
//! made 0.68× the proposals of one (each reader waiting out a commit slept 10× its length); after
//! 65,536 rounds 1.33×, as spinning (1.32×), and in the page two threads gained 1.17× either way;
//! not kept. Satisfy Lockable (std::lock_guard works).
//!   SpinLock:   a few dozen nanoseconds held (a hash-table probe)
//!   CommitLock: up to a few microseconds held (the annealer's commit section), exclusively, or
//!               shared by readers (lock_shared) that only read what commits write

#include <atomic>
#include <cstdint>
#include <thread>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace zomeify {

//! Tells the core it is in a spin-wait loop (x86: PAUSE; elsewhere nothing).
inline void cpu_relax() noexcept
{
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#endif
}

template <int SpinsBeforeYield>
class BasicSpinLock
{
public:
    void lock() noexcept
    {
        for (int spins = 0; locked_.exchange(true, std::memory_order_acquire);)
        {
            while (locked_.load(std::memory_order_relaxed))
            {
                cpu_relax();
                if (++spins > SpinsBeforeYield)
                {
                    std::this_thread::yield();
                    spins = 0;
                }
            }
        }
    }
    bool try_lock() noexcept { return !locked_.exchange(true, std::memory_order_acquire); }
    void unlock() noexcept { locked_.store(false, std::memory_order_release); }

private:
    std::atomic<bool> locked_{false};
};

//! A reader-writer spin lock: lock() is exclusive, lock_shared() lets any number of readers in at
//! once. A waiting writer keeps new readers out, so commits are not starved by a stream of readers.
template <int SpinsBeforeYield>
class BasicSharedSpinLock
{
public:
    void lock() noexcept
    {
        int spins = 0;
        uint32_t s = state_.load(std::memory_order_relaxed);
        while ((s & kWriter) ||
               !state_.compare_exchange_weak(s, s | kWriter, std::memory_order_acquire, std::memory_order_relaxed))
        {
            wait(spins);
            s = state_.load(std::memory_order_relaxed);
        }
        while (state_.load(std::memory_order_acquire) != kWriter)
            wait(spins); // readers leave
    }
    bool try_lock() noexcept
    {
        uint32_t s = 0;
        return state_.compare_exchange_strong(s, kWriter, std::memory_order_acquire, std::memory_order_relaxed);
    }
    void unlock() noexcept { state_.fetch_and(~kWriter, std::memory_order_release); }

    void lock_shared() noexcept
    {
        int spins = 0;
        uint32_t s = state_.load(std::memory_order_relaxed);
        while ((s & kWriter) ||
               !state_.compare_exchange_weak(s, s + 1, std::memory_order_acquire, std::memory_order_relaxed))
        {
            wait(spins);
            s = state_.load(std::memory_order_relaxed);
        }
    }
    void unlock_shared() noexcept { state_.fetch_sub(1, std::memory_order_release); }

private:
    static constexpr uint32_t kWriter = 0x80000000U;
    static void wait(int& spins) noexcept
    {
        cpu_relax();
        if (++spins > SpinsBeforeYield)
        {
            std::this_thread::yield();
            spins = 0;
        }
    }
    std::atomic<uint32_t> state_{0};
};

using SpinLock = BasicSpinLock<64>;
using CommitLock = BasicSharedSpinLock<2048>;

} // namespace zomeify
