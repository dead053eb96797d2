// PauseBarrier: the maintenance runs alone, with every other worker parked; stopping releases all.
#include <atomic>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/anneal/engine/pause_barrier.h"

namespace zomeify {
namespace {

TEST(AnnealParallel, PauseBarrierRunsMaintenanceAlone)
{
    constexpr int kWorkers = 6, kRounds = 200;
    PauseBarrier barrier(kWorkers);
    std::atomic<bool> stop{false};
    std::atomic<int> inside{kWorkers}; // workers between two barrier passes, doing "work"
    std::atomic<int> maintenances{0};
    bool overlap = false; // written only by the maintenance (alone by contract)
    std::vector<std::thread> threads;
    for (int w = 0; w < kWorkers; ++w)
        threads.emplace_back([&, w] {
            int rounds = 0;
            while (!stop.load())
            {
                if (barrier.requested())
                {
                    inside.fetch_sub(1);
                    barrier.arrive(stop, [&] {
                        overlap = overlap || inside.load() != 0;
                        if (maintenances.fetch_add(1) + 1 == kRounds)
                            stop.store(true);
                    });
                    inside.fetch_add(1);
                    continue;
                }
                if (w == rounds % kWorkers)
                    barrier.request();
                ++rounds;
                std::this_thread::yield();
            }
            inside.fetch_sub(1);
            barrier.leave([] {});
        });
    for (auto& t : threads)
        t.join();
    EXPECT_FALSE(overlap);
    EXPECT_GE(maintenances.load(), kRounds);
}

TEST(AnnealParallel, PauseBarrierReleasesWaitersOnStop)
{
    PauseBarrier barrier(3);
    std::atomic<bool> stop{false};
    std::atomic<int> returned{0};
    barrier.request();
    std::vector<std::thread> waiters;
    for (int i = 0; i < 2; ++i)
        waiters.emplace_back([&] {
            barrier.arrive(stop, [] {});
            returned.fetch_add(1);
        });
    // The third worker never arrives: it stops and leaves, which must free the other two.
    stop.store(true);
    barrier.wake_all();
    barrier.leave([] {});
    for (auto& t : waiters)
        t.join();
    EXPECT_EQ(returned.load(), 2);
}

} // namespace
} // namespace zomeify
