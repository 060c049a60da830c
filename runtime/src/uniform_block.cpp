#include <atomic>

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

uint64_t nextUniformGeneration() {
  // Starts at 1: 0 is what a default-constructed UniformBlock carries.
  static std::atomic<uint64_t> next{1};
  return next.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace facet::runtime
