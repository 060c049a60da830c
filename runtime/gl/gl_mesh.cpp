#include "gl_mesh.h"

#include <algorithm>
#include <cstdint>

namespace facet::runtime::gl {
namespace {

void vertexAttribute(GLuint location, GLint components, size_t offsetBytes) {
  glEnableVertexAttribArray(location);
  // GL takes a buffer offset through the pointer parameter.
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(abi::kVertexStride),
                        reinterpret_cast<const void*>(offsetBytes));
}

}  // namespace

bool uploadMesh(const Mesh& mesh, MeshBuffers* buffers, std::string* error) {
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

  MeshBuffers uploaded;
  uploaded.vertexArray = VertexArray::generate();
  uploaded.vertices = Buffer::generate();
  uploaded.indices = Buffer::generate();
  uploaded.indexCount = static_cast<GLsizei>(mesh.indices.size());

  glBindVertexArray(uploaded.vertexArray.id());
  glBindBuffer(GL_ARRAY_BUFFER, uploaded.vertices.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(float)), mesh.vertices.data(),
               GL_STATIC_DRAW);
  // The element array binding is VAO state, so it is bound while the VAO is.
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, uploaded.indices.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  for (const abi::VertexAttribute& a : abi::kVertexAttributes)
    vertexAttribute(a.location, GLint(a.components), a.offsetFloats * sizeof(float));
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
  if (!uploadMesh(mesh, &entry.buffers, error)) return nullptr;
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
