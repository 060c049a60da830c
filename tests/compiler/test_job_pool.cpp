// The compiler's job pool (compiler/src/job_pool.h): every job runs once, including the ones jobs
// add; the costliest waiting job starts first; N threads run N jobs at once.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <vector>

#include "job_pool.h"

using facet::compiler::JobPool;

TEST(JobPool, RunsEveryJobAndEveryJobAJobAddsExactlyOnce) {
  constexpr size_t kParents = 64;
  std::array<std::atomic<int>, kParents * 3> runs{};
  JobPool pool;
  for (size_t i = 0; i < kParents; ++i)
    pool.add(double(i % 7), [&runs, i](JobPool& p) {
      ++runs[i];
      // Two follow-ups, as a variant's glslang job adds its two stages.
      p.add(1, [&runs, i](JobPool&) { ++runs[kParents + 2 * i]; });
      p.add(2, [&runs, i](JobPool&) { ++runs[kParents + 2 * i + 1]; });
    });
  pool.run(2);
  for (size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << "job " << i;
}

TEST(JobPool, StartsTheCostliestWaitingJobFirstAndTiesInTheOrderAdded) {
  std::vector<int> order;
  JobPool pool;
  pool.add(1, [&](JobPool&) { order.push_back(1); });
  pool.add(5, [&](JobPool& p) {
    order.push_back(5);
    // Added while the cost-3 job waits: the costlier one overtakes it, the cheaper one does not.
    p.add(4, [&](JobPool&) { order.push_back(4); });
    p.add(2, [&](JobPool&) { order.push_back(2); });
  });
  pool.add(3, [&](JobPool&) { order.push_back(3); });
  pool.add(5, [&](JobPool&) { order.push_back(50); });
  pool.run(1);
  EXPECT_EQ(order, (std::vector<int>{5, 50, 4, 3, 2, 1}));
}

// Two jobs that each wait for the other to have started finish only if two threads run them at
// once (bounded wait: a pool that ran them one after the other fails instead of hanging).
TEST(JobPool, TwoThreadsRunTwoJobsAtOnce) {
  std::mutex mutex;
  std::condition_variable changed;
  int started = 0;
  std::atomic<int> metTheOther{0};
  auto job = [&](JobPool&) {
    std::unique_lock<std::mutex> lock(mutex);
    ++started;
    changed.notify_all();
    if (changed.wait_for(lock, std::chrono::seconds(20), [&] { return started == 2; })) ++metTheOther;
  };
  JobPool pool;
  pool.add(1, job);
  pool.add(1, job);
  pool.run(2);
  EXPECT_EQ(metTheOther.load(), 2);
}
