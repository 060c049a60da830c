#include "vk_meshes.h"

namespace facet::runtime::vulkan {

void MeshCache::destroy() {
  if (!allocator_) return;
  for (auto& [mesh, entry] : meshes_) allocator_->release(&entry.buffer);
  meshes_.clear();
}

void MeshCache::release(const Entry& entry) {
  retire_->retire([allocator = allocator_, buffer = entry.buffer]() mutable { allocator->release(&buffer); });
}

bool MeshCache::upload(const Mesh& mesh, Entry* entry, std::string* error) {
  PackedMesh packed;
  if (!packMesh(mesh, packing_, &packed, error)) return false;
  MeshLocation& location = entry->location;
  location.vertexCount = packed.vertexCount;
  location.indexCount = static_cast<uint32_t>(mesh.indices.size());
  location.layout = packed.layout;
  location.decode = packed.decode;
  // Every stride is a multiple of 4 bytes, so each stream, and the indices after them, start at
  // the 4-byte offset vkCmdBindIndexBuffer requires for UINT32.
  VkDeviceSize offset = 0;
  for (uint32_t s = 0; s < abi::kVertexStreams; ++s) {
    location.streamOffsets[s] = offset;
    offset += packed.streams[s].size();
  }
  location.indexOffset = offset;
  const VkDeviceSize indexBytes = mesh.indices.size() * sizeof(uint32_t);
  if (packed.vertexCount == 0) return true;
  if (!allocator_->create(
          offset + indexBytes,
          VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
          BufferUse::DeviceRead, &entry->buffer, error)) {
    return false;
  }
  for (uint32_t s = 0; s < abi::kVertexStreams; ++s)
    uploads_->write(entry->buffer, location.streamOffsets[s], packed.streams[s].data(), packed.streams[s].size());
  uploads_->write(entry->buffer, location.indexOffset, mesh.indices.data(), indexBytes);
  location.buffer = entry->buffer.buffer;
  ++uploadCount_;
  return true;
}

bool MeshCache::prepare(const FrameDesc& frame, std::string* error) {
  ++frameNumber_;
  const FrameDraws draws(frame);
  for (size_t i = 0; i < draws.size(); ++i) {
    const DrawItem& draw = draws[i];
    auto found = meshes_.find(draw.mesh);
    // Already seen this frame: its identity was checked by the first draw of it.
    if (found != meshes_.end() && found->second.lastUsedFrame == frameNumber_) continue;
    MeshIdentity key = MeshIdentity::of(*draw.mesh);
    if (found != meshes_.end()) {
      if (found->second.key == key) {
        found->second.lastUsedFrame = frameNumber_;
        continue;
      }
      release(found->second);  // edited in place, or a new mesh
      meshes_.erase(found);
    }
    Entry entry;
    entry.key = key;
    entry.lastUsedFrame = frameNumber_;
    if (!upload(*draw.mesh, &entry, error)) {
      *error = "draw " + std::to_string(i) + ": " + *error;
      allocator_->release(&entry.buffer);
      return false;
    }
    meshes_.emplace(draw.mesh, entry);
  }
  // Eviction: a mesh gone from the scene must not hold memory forever.
  evictUnusedEntries(meshes_, frameNumber_, [&](const Entry& entry) { release(entry); });
  return true;
}

MeshLocation MeshCache::locate(const Mesh* mesh) const {
  auto found = meshes_.find(mesh);
  return found == meshes_.end() ? MeshLocation{} : found->second.location;
}

}  // namespace facet::runtime::vulkan
