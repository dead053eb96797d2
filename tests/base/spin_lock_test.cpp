// The spin locks (core/base/spin_lock.h): mutual exclusion under contention, also with more
// threads than cores (waiters must yield to a preempted holder), and try_lock.
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/spin_lock.h"

namespace zomeify {
namespace {

// Threads add to a plain (non-atomic) counter and a pair that must stay equal under the lock:
// without exclusion increments are lost and the pair is seen torn (and ThreadSanitizer reports).
template <class Lock>
void expect_exclusive(int threads, int rounds)
{
    Lock lock;
    long counter = 0;
    long a = 0, b = 0;
    bool torn = false;
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
    {
        pool.emplace_back([&] {
            for (int i = 0; i < rounds; ++i)
            {
                std::lock_guard guard(lock);
                ++counter;
                ++a;
                if (a != b + 1)
                    torn = true;
                ++b;
            }
        });
    }
    for (std::thread& th : pool)
        th.join();
    EXPECT_EQ(counter, static_cast<long>(threads) * rounds);
    EXPECT_EQ(a, b);
    EXPECT_FALSE(torn);
}

TEST(SpinLocksParallel, ExclusiveUnderContention)
{
    expect_exclusive<SpinLock>(4, 20000);
    expect_exclusive<CommitLock>(4, 20000);
}

TEST(SpinLocksParallel, MoreThreadsThanCoresFinish)
{
    // Eight threads on this machine's two cores: a holder is preempted now and then, and the
    // waiters' yield lets it run again.
    expect_exclusive<CommitLock>(8, 5000);
}

TEST(SpinLocksParallel, TryLock)
{
    CommitLock lock;
    EXPECT_TRUE(lock.try_lock());
    EXPECT_FALSE(lock.try_lock());
    bool other = true;
    std::thread([&] { other = lock.try_lock(); }).join();
    EXPECT_FALSE(other);
    lock.unlock();
    std::thread([&] {
        other = lock.try_lock();
        if (other)
            lock.unlock();
    }).join();
    EXPECT_TRUE(other);
}

} // namespace
} // namespace zomeify
