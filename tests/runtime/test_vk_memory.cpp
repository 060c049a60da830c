// The Vulkan backend's buffer sub-allocator (runtime/vulkan/vk_memory.h), on the machine's
// device (lavapipe on CI): many buffers share a block, released space is reused, and a buffer
// replaced every frame does not creep through memory.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "vk_context.h"
#include "vk_memory.h"

namespace facet::runtime::vulkan {
namespace {

struct AllocatorFixture {
  Context ctx;
  BufferAllocator allocator;
  bool ok = false;
  AllocatorFixture() {
    std::string error;
    ok = ctx.init(/*validation=*/true, /*float16Arithmetic=*/false, /*renderToSingleSampled=*/false, &error);
    EXPECT_TRUE(ok) << error;
    allocator.init(&ctx, false);
  }
  ~AllocatorFixture() { allocator.destroy(); }
  BufferAllocation make(VkDeviceSize size) {
    BufferAllocation a;
    std::string error;
    EXPECT_TRUE(allocator.create(size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, BufferUse::DeviceRead, &a, &error)) << error;
    return a;
  }
};

TEST(BufferAllocator, ThousandsOfBuffersShareOneAllocation) {
  AllocatorFixture f;
  ASSERT_TRUE(f.ok);
  const uint64_t before = f.ctx.memoryAllocations;
  std::vector<BufferAllocation> buffers;
  for (int i = 0; i < 3000; ++i) buffers.push_back(f.make(256));
  EXPECT_EQ(f.ctx.memoryAllocations - before, 1u);
  EXPECT_EQ(f.allocator.blockCount(), 1u);
  // Distinct, non-overlapping ranges of the one block.
  for (size_t i = 1; i < buffers.size(); ++i) EXPECT_GE(buffers[i].offset, buffers[i - 1].offset + 256);
  for (BufferAllocation& b : buffers) f.allocator.release(&b);
  EXPECT_EQ(f.allocator.bytesBelowTops(), 0u);  // empty: starts over
  EXPECT_TRUE(f.ctx.messages.errors.empty()) << f.ctx.messages.errors.front();
}

TEST(BufferAllocator, ReleasedSpaceIsReusedAndMerged) {
  AllocatorFixture f;
  ASSERT_TRUE(f.ok);
  BufferAllocation a = f.make(1024), b = f.make(1024), c = f.make(1024), keep = f.make(64);
  const VkDeviceSize aAt = a.offset;
  f.allocator.release(&a);
  f.allocator.release(&b);  // merges with a's range
  BufferAllocation big = f.make(2048);
  EXPECT_EQ(big.offset, aAt);  // a and b's space, merged, holds it
  f.allocator.release(&big);
  f.allocator.release(&c);
  f.allocator.release(&keep);
  EXPECT_EQ(f.allocator.bytesBelowTops(), 0u);
}

// A material block replaced every frame while a mesh stays: the block's space is reused, so
// 20,000 replacements fill no more of the block than a few buffers.
TEST(BufferAllocator, BufferReplacedEveryFrameDoesNotCreep) {
  AllocatorFixture f;
  ASSERT_TRUE(f.ok);
  BufferAllocation mesh = f.make(4096);
  BufferAllocation block = f.make(256);
  const uint64_t before = f.ctx.memoryAllocations;
  for (int frame = 0; frame < 20000; ++frame) {
    BufferAllocation next = f.make(256);  // the new one exists before the old is released
    f.allocator.release(&block);
    block = next;
  }
  EXPECT_EQ(f.ctx.memoryAllocations, before);
  EXPECT_LE(f.allocator.bytesBelowTops(), 4096u + 4 * 1024u);
  f.allocator.release(&block);
  f.allocator.release(&mesh);
}

}  // namespace
}  // namespace facet::runtime::vulkan
