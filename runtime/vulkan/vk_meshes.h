// Meshes on the device: one buffer per distinct Mesh (its two packed vertex streams,
// vertex_packing.h, then its indices), uploaded when the mesh is first drawn and shared by every
// draw of it, in this frame and later ones.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <unordered_map>

#include "facet/runtime/frame_eviction.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/vertex_packing.h"
#include "vk_memory.h"
#include "vk_retire.h"
#include "vk_uploads.h"

namespace facet::runtime::vulkan {

// Where a resident mesh is. buffer is null for a mesh without vertices (nothing is drawn).
struct MeshLocation {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize streamOffsets[abi::kVertexStreams] = {};
  VkDeviceSize indexOffset = 0;
  VertexLayout layout = VertexLayout::FullPrecision;  // the pipeline's vertex input state
  VertexDecode decode;                                // the draw's ObjectUniforms carry it
  uint32_t vertexCount = 0;
  uint32_t indexCount = 0;  // 0: non-indexed draw of vertexCount vertices
};

// Device buffers of the Meshes a backend has drawn with, keyed by the Mesh's address: each its
// own VkBuffer, sub-allocated from shared device-local memory (vk_memory.h).
//
// Cache rule (as TextureCache's): an entry is reused while the Mesh at that address has the same
// MeshIdentity (sizes and a hash of its bytes, hashed once per distinct mesh per frame); one
// unused for kEvictAfterFrames frames is released. A buffer is written once, at creation,
// through UploadQueue: directly where device-local memory is host-visible (phones, lavapipe),
// else by a staging copy recorded before the frame's passes.
class MeshCache {
 public:
  MeshCache() = default;
  MeshCache(const MeshCache&) = delete;
  MeshCache& operator=(const MeshCache&) = delete;

  // The three must outlive this cache, and destroy() must be called before the allocator's.
  // Replaced and evicted buffers go through `retire`: frames in flight may use them.
  void init(BufferAllocator* allocator, UploadQueue* uploads, RetireQueue* retire, VertexPacking packing) {
    packing_ = packing;
    allocator_ = allocator;
    uploads_ = uploads;
    retire_ = retire;
  }
  // Releases every buffer. The device must be idle. Safe to call twice.
  void destroy();

  // Makes every mesh of the (already checked) frame's FrameDraws resident, then releases the entries unused
  // for too long. A changed mesh gets a new buffer; the old one is retired.
  bool prepare(const FrameDesc& frame, std::string* error);
  // The location of a mesh that went through prepare() this frame.
  MeshLocation locate(const Mesh* mesh) const;

  size_t residentCount() const { return meshes_.size(); }
  uint64_t uploadCount() const { return uploadCount_; }

 private:
  struct Entry {
    MeshIdentity key;
    BufferAllocation buffer;  // empty for a mesh without vertices
    MeshLocation location;
    uint64_t lastUsedFrame = 0;
  };

  bool upload(const Mesh& mesh, Entry* entry, std::string* error);

  void release(const Entry& entry);

  VertexPacking packing_ = VertexPacking::Packed;
  BufferAllocator* allocator_ = nullptr;
  UploadQueue* uploads_ = nullptr;
  RetireQueue* retire_ = nullptr;
  std::unordered_map<const Mesh*, Entry> meshes_;
  uint64_t frameNumber_ = 0;
  uint64_t uploadCount_ = 0;
};

}  // namespace facet::runtime::vulkan
