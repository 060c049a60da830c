// The rule every backend cache of GPU copies shares (meshes, textures, uniform blocks on Vulkan
// and GL): an entry unused for kEvictAfterFrames frames is released, so what leaves a scene does
// not hold memory forever, while what is drawn every frame, or every few, is never uploaded again.
#pragma once

#include <cstdint>

namespace facet::runtime {

inline constexpr uint64_t kEvictAfterFrames = 16;

// Erases from `entries` (a map whose values have `uint64_t lastUsedFrame`) those unused for
// kEvictAfterFrames frames as of `frameNumber`, calling release(value) on each first (GL objects
// release themselves on destruction: pass a function that does nothing).
template <typename Map, typename Release>
void evictUnusedEntries(Map& entries, uint64_t frameNumber, Release release) {
  for (auto it = entries.begin(); it != entries.end();) {
    if (frameNumber - it->second.lastUsedFrame >= kEvictAfterFrames) {
      release(it->second);
      it = entries.erase(it);
    } else {
      ++it;
    }
  }
}

}  // namespace facet::runtime
