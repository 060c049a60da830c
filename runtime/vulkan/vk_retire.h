// Deferred destruction of Vulkan objects that a frame still in flight may use. With recordFrame
// (vulkan_backend.h) the app submits and waits, so the backend cannot know when a buffer,
// pipeline or framebuffer it replaces stops being read; it only knows the app's promise: when
// frame k is recorded, frame k - framesInFlight has finished on the device. An object retired
// while frame t is prepared may be referenced by frames up to t, so it is destroyed when frame
// t + framesInFlight is recorded. render() waits for its own fence (and so for everything
// submitted before it on the queue) and releases everything.
#pragma once

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace facet::runtime::vulkan {

class RetireQueue {
 public:
  // Frames are numbered by the backend, one per render()/renderToImage()/recordFrame() call.
  void beginFrame(uint64_t frame) { frame_ = frame; }
  void retire(std::function<void()> release) { pending_.emplace_back(frame_, std::move(release)); }
  // Destroys what was retired while frames <= `frame` were prepared.
  void releaseThrough(uint64_t frame) {
    std::vector<std::pair<uint64_t, std::function<void()>>> keep;
    for (auto& [retiredAt, release] : pending_) {
      if (retiredAt <= frame) {
        release();
      } else {
        keep.emplace_back(retiredAt, std::move(release));
      }
    }
    pending_ = std::move(keep);
  }
  void releaseAll() {
    for (auto& item : pending_) item.second();
    pending_.clear();
  }
  size_t size() const { return pending_.size(); }

 private:
  uint64_t frame_ = 0;
  std::vector<std::pair<uint64_t, std::function<void()>>> pending_;
};

}  // namespace facet::runtime::vulkan
