// A fixed pool of threads working through a list of jobs, largest estimated cost first, where a
// running job may add jobs (the next steps of its work once their input exists). Scheduling
// decides only when a job runs, never what it computes: callers write each job's result into its
// own slot and read the slots in a fixed order, so the output is the same for any thread count.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <queue>
#include <vector>

namespace facet::compiler {

class JobPool {
 public:
  using Job = std::function<void(JobPool&)>;

  // Adds a job; callable before run() and from running jobs. Among the jobs waiting, the one with
  // the highest `cost` starts next (ties: the one added first). Longest first is what keeps two
  // threads busy to the end: the short jobs are left to fill the gaps (Graham's LPT rule).
  void add(double cost, Job job);

  // Runs every job, including the ones jobs add, on up to `threads` threads (the caller's thread
  // is one of them; 0 means one per hardware thread), and returns when none is left.
  void run(unsigned threads);

  // Which of run()'s threads calls this, 0 .. threads-1 (0 is run()'s caller); 0 outside a pool.
  static unsigned currentThread();

 private:
  struct Waiting {
    double cost;
    uint64_t order;
    Job job;
    bool operator<(const Waiting& other) const {
      return cost != other.cost ? cost < other.cost : order > other.order;  // top(): highest cost, then first added
    }
  };
  void work(unsigned thread);

  std::mutex mutex_;
  std::condition_variable changed_;
  std::priority_queue<Waiting> waiting_;
  uint64_t added_ = 0;
  size_t running_ = 0;
};

// The thread count `threads == 0` stands for.
unsigned defaultJobCount();

}  // namespace facet::compiler
