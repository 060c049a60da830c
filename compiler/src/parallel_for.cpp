#include "parallel_for.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace facet::compiler {

unsigned defaultJobCount() { return std::max(1u, std::thread::hardware_concurrency()); }

void parallelFor(size_t count, unsigned jobs, const std::function<bool(size_t)>& work) {
  if (jobs == 0) jobs = defaultJobCount();
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  auto worker = [&] {
    while (!failed.load()) {
      size_t i = next.fetch_add(1);
      if (i >= count) return;
      if (!work(i)) failed.store(true);
    }
  };
  size_t threads = std::min<size_t>(jobs, count);
  std::vector<std::thread> helpers;
  for (size_t t = 1; t < threads; ++t) helpers.emplace_back(worker);
  worker();
  for (std::thread& t : helpers) t.join();
}

}  // namespace facet::compiler
