// Meshes on the device: one buffer per distinct Mesh (vertices, then indices), uploaded when the
// mesh is first drawn and shared by every draw of it, in this frame and later ones.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <unordered_map>

#include "facet/render_backend.h"
#include "facet/runtime/mesh.h"
#include "facet/frame_eviction.h"
#include "vk_resources.h"
#include "vk_retire.h"

namespace facet::runtime::vulkan {

class Context;

// Where a resident mesh is. buffer is null for a mesh without vertices (nothing is drawn).
struct MeshLocation {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize indexOffset = 0;
  uint32_t vertexCount = 0;
  uint32_t indexCount = 0;  // 0: non-indexed draw of vertexCount vertices
};

// Device buffers of the Meshes a backend has drawn with, keyed by the Mesh's address.
//
// Cache rule (as TextureCache's): an entry is reused while the Mesh at that address has the same
// MeshIdentity (sizes and a hash of its bytes, hashed once per distinct mesh per frame); one
// unused for kEvictAfterFrames frames is released. The buffers are host-visible and coherent,
// written once at creation: on the unified memory of phones (and lavapipe) that is device
// memory; a discrete GPU would want a staging copy into device-local memory (not done).
class MeshCache {
 public:
  MeshCache() = default;
  MeshCache(const MeshCache&) = delete;
  MeshCache& operator=(const MeshCache&) = delete;

  // ctx and retire must outlive this cache, and destroy() must be called before the device is
  // destroyed. Replaced and evicted buffers go through `retire`: frames in flight may use them.
  void init(const Context* ctx, RetireQueue* retire) {
    ctx_ = ctx;
    retire_ = retire;
  }
  // Releases every buffer. The device must be idle. Safe to call twice.
  void destroy();

  // Makes every mesh of the (already checked) frame resident, then releases the entries unused
  // for too long. A changed mesh gets a new buffer; the old one is retired.
  bool prepare(const FrameDesc& frame, std::string* error);
  // The location of a mesh that went through prepare() this frame.
  MeshLocation locate(const Mesh* mesh) const;

  size_t residentCount() const { return meshes_.size(); }
  uint64_t uploadCount() const { return uploads_; }

 private:
  struct Entry {
    MeshIdentity key;
    HostBuffer buffer;  // empty for a mesh without vertices
    MeshLocation location;
    uint64_t lastUsedFrame = 0;
  };

  bool upload(const Mesh& mesh, Entry* entry, std::string* error);

  void release(const Entry& entry);

  const Context* ctx_ = nullptr;
  RetireQueue* retire_ = nullptr;
  std::unordered_map<const Mesh*, Entry> meshes_;
  uint64_t frameNumber_ = 0;
  uint64_t uploads_ = 0;
};

}  // namespace facet::runtime::vulkan
