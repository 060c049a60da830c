#include "gl_mesh.h"

#include <algorithm>
#include <cstdint>

namespace facet::runtime::gl {
namespace {

// GL's description of a stream attribute: the shader reads every one as float vecN.
struct GlFormat {
  GLint size;
  GLenum type;
  GLboolean normalized;
};
GlFormat glFormat(VertexFormat format) {
  switch (format) {
    case VertexFormat::Float32x2: return {2, GL_FLOAT, GL_FALSE};
    case VertexFormat::Float32x3: return {3, GL_FLOAT, GL_FALSE};
    case VertexFormat::Float32x4: return {4, GL_FLOAT, GL_FALSE};
    case VertexFormat::Snorm16x4: return {4, GL_SHORT, GL_TRUE};
    case VertexFormat::Unorm16x2: return {2, GL_UNSIGNED_SHORT, GL_TRUE};
    // Core in GLES 3.0 (and its max(c / 511, −1) conversion, which keeps ±1 exact).
    case VertexFormat::Snorm10x3w2: return {4, GL_INT_2_10_10_10_REV, GL_TRUE};
    case VertexFormat::Unorm8x4: return {4, GL_UNSIGNED_BYTE, GL_TRUE};
  }
  return {4, GL_FLOAT, GL_FALSE};
}

}  // namespace

bool uploadMesh(const Mesh& mesh, VertexPacking packing, MeshBuffers* buffers, std::string* error) {
  if (mesh.vertices.empty() || mesh.vertices.size() % abi::kVertexFloats != 0) {
    if (error) {
      *error = "mesh has " + std::to_string(mesh.vertices.size()) + " floats, not a positive multiple of " +
               std::to_string(abi::kVertexFloats) + " (shader_abi.h's vertex layout)";
    }
    return false;
  }
  if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) {
    if (error) *error = "mesh has " + std::to_string(mesh.indices.size()) + " indices, not a whole triangle list";
    return false;
  }
  const size_t vertexCount = mesh.vertices.size() / abi::kVertexFloats;
  const uint32_t maxIndex = *std::max_element(mesh.indices.begin(), mesh.indices.end());
  if (maxIndex >= vertexCount) {
    if (error) {
      *error =
          "mesh index " + std::to_string(maxIndex) + " is out of range (" + std::to_string(vertexCount) + " vertices)";
    }
    return false;
  }
  PackedMesh packed;
  std::string why;
  if (!packMesh(mesh, packing, &packed, &why)) {
    if (error) *error = why;
    return false;
  }

  MeshBuffers uploaded;
  uploaded.vertexArray = VertexArray::generate();
  uploaded.indices = Buffer::generate();
  uploaded.indexCount = static_cast<GLsizei>(mesh.indices.size());
  uploaded.decode = packed.decode;

  glBindVertexArray(uploaded.vertexArray.id());
  const VertexLayoutDesc& layout = vertexLayout(packed.layout);
  for (uint32_t s = 0; s < abi::kVertexStreams; ++s) {
    uploaded.streams[s] = Buffer::generate();
    glBindBuffer(GL_ARRAY_BUFFER, uploaded.streams[s].id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(packed.streams[s].size()), packed.streams[s].data(),
                 GL_STATIC_DRAW);
    // The attribute pointers take the buffer bound now.
    for (const StreamAttribute& a : layout.attributes) {
      if (a.stream != s) continue;
      const GlFormat f = glFormat(a.format);
      glEnableVertexAttribArray(a.location);
      // GL takes a buffer offset through the pointer parameter.
      glVertexAttribPointer(a.location, f.size, f.type, f.normalized, static_cast<GLsizei>(layout.strides[s]),
                            reinterpret_cast<const void*>(size_t(a.offset)));
    }
  }
  // The instance stream's attributes advance once per instance (divisor 1, VAO state); their
  // pointers are set per draw, into the frame's instance buffer (GLES 3.0 has no base instance).
  for (const abi::VertexAttribute& a : abi::kInstanceAttributes) {
    glEnableVertexAttribArray(a.location);
    glVertexAttribDivisor(a.location, 1);
  }
  // The element array binding is VAO state, so it is bound while the VAO is.
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, uploaded.indices.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);

  if (!checkGlError("mesh upload", error)) return false;
  *buffers = std::move(uploaded);
  return true;
}

const MeshBuffers* MeshCache::resident(const Mesh& mesh, std::string* error) {
  auto found = meshes_.find(&mesh);
  // Already seen this frame: its identity was checked by the first draw of it.
  if (found != meshes_.end() && found->second.lastUsedFrame == frameNumber_) return &found->second.buffers;
  MeshIdentity key = MeshIdentity::of(mesh);
  if (found != meshes_.end() && found->second.key == key) {
    found->second.lastUsedFrame = frameNumber_;
    return &found->second.buffers;
  }
  Entry entry;
  entry.key = key;
  entry.lastUsedFrame = frameNumber_;
  if (!uploadMesh(mesh, packing_, &entry.buffers, error)) return nullptr;
  ++uploads_;
  // A changed mesh's old buffers are deleted here; earlier draws that used them keep their
  // contents (GL orphans storage still referenced by queued commands).
  Entry& stored = meshes_[&mesh];
  stored = std::move(entry);
  return &stored.buffers;
}

void MeshCache::endFrame() {
  evictUnusedEntries(meshes_, frameNumber_, [](auto&) {});  // GL objects delete themselves
}

}  // namespace facet::runtime::gl
