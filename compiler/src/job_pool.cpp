#include "job_pool.h"

#include <algorithm>
#include <thread>

namespace facet::compiler {
namespace {
thread_local unsigned tCurrentThread = 0;
}  // namespace

unsigned JobPool::currentThread() { return tCurrentThread; }

unsigned defaultJobCount() { return std::max(1u, std::thread::hardware_concurrency()); }

void JobPool::add(double cost, Job job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    waiting_.push({cost, added_++, std::move(job)});
  }
  changed_.notify_one();
}

void JobPool::work(unsigned thread) {
  tCurrentThread = thread;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    // Idle threads wait while a running job may still add work; none waiting and none running
    // is the end.
    changed_.wait(lock, [&] { return !waiting_.empty() || running_ == 0; });
    if (waiting_.empty()) break;
    Job job = std::move(const_cast<Waiting&>(waiting_.top()).job);  // moved out, then popped
    waiting_.pop();
    ++running_;
    lock.unlock();
    job(*this);
    lock.lock();
    --running_;
    if (running_ == 0 && waiting_.empty()) changed_.notify_all();
  }
  tCurrentThread = 0;
}

void JobPool::run(unsigned threads) {
  if (threads == 0) threads = defaultJobCount();
  std::vector<std::thread> helpers;
  for (unsigned t = 1; t < threads; ++t) helpers.emplace_back([this, t] { work(t); });
  work(0);
  for (std::thread& t : helpers) t.join();
}

}  // namespace facet::compiler
