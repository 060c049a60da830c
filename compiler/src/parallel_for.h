// A fixed pool of threads working through indices 0..count-1 in order. Deterministic by
// construction for callers that write result i into slot i and read the slots in index order.
#pragma once

#include <cstddef>
#include <functional>

namespace facet::compiler {

// Calls work(i) for every i < count on up to `jobs` threads (the caller's thread is one of them;
// jobs == 0 means one per hardware thread). When work returns false no further index is started,
// but every index already started finishes: all indices below the first failing one have run,
// so "the first failure in index order" does not depend on the job count or on timing.
void parallelFor(size_t count, unsigned jobs, const std::function<bool(size_t)>& work);

// The job count `jobs == 0` stands for.
unsigned defaultJobCount();

}  // namespace facet::compiler
