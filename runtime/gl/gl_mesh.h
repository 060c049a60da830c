// A Mesh packed (vertex_packing.h) and uploaded into GL buffers: the two streams of shader_abi.h.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>

#include "facet/runtime/frame_eviction.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/vertex_packing.h"
#include "gl_objects.h"

namespace facet::runtime::gl {

struct MeshBuffers {
  VertexArray vertexArray;  // records the streams' formats and the index buffer binding
  Buffer streams[abi::kVertexStreams];
  Buffer indices;
  GLsizei indexCount = 0;
  VertexDecode decode;  // what the draw's ObjectUniforms carry to the vertex shader
};

// Checks the mesh (whole vertices, finite values, indices in range), packs and uploads it.
// Returns false with *error set on a malformed mesh: an out-of-range index would read past the
// buffer in the driver.
bool uploadMesh(const Mesh& mesh, VertexPacking packing, MeshBuffers* buffers, std::string* error);

// GL buffers of the Meshes a backend has drawn with, keyed by the Mesh's address, shared by every
// draw of a mesh in this frame and later ones. Cache rule as vulkan::MeshCache's (vk_meshes.h):
// reused while the MeshIdentity (sizes, hash of the bytes; hashed once per mesh per frame) is
// unchanged, deleted after kEvictAfterFrames frames unused.
class MeshCache {
 public:
  explicit MeshCache(VertexPacking packing = VertexPacking::Packed) : packing_(packing) {}
  void beginFrame() { ++frameNumber_; }
  // The mesh's buffers, uploaded if new or changed; nullptr with *error set on a malformed mesh.
  const MeshBuffers* resident(const Mesh& mesh, std::string* error);
  // Deletes the entries unused for too long.
  void endFrame();

  size_t residentCount() const { return meshes_.size(); }
  uint64_t uploadCount() const { return uploads_; }

 private:
  struct Entry {
    MeshIdentity key;
    MeshBuffers buffers;
    uint64_t lastUsedFrame = 0;
  };

  VertexPacking packing_;
  std::unordered_map<const Mesh*, Entry> meshes_;
  uint64_t frameNumber_ = 0;
  uint64_t uploads_ = 0;
};

}  // namespace facet::runtime::gl
