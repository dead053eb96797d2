#pragma once
//! \file spin_lock.h
//! A lock for critical sections of a few dozen nanoseconds (a hash-table probe). Unlike a mutex it
//! never enters the kernel and its unlock is a plain store, so an uncontended lock/unlock pair costs
//! one atomic exchange. Waiters spin on a load (no writes while the line is held) and yield to the
//! scheduler after a while, so a holder preempted on an oversubscribed machine is not starved.
//! Satisfies Lockable (std::lock_guard works).

#include <atomic>
#include <thread>

namespace zomeify {

class SpinLock
{
public:
    void lock() noexcept
    {
        for (int spins = 0; locked_.exchange(true, std::memory_order_acquire); )
        {
            while (locked_.load(std::memory_order_relaxed))
            {
                if (++spins > 64)
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

} // namespace zomeify
