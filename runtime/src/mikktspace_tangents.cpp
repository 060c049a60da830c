#include "mikktspace_tangents.h"

#include <array>
#include <cstring>
#include <map>
#include <vector>

#include <mikktspace.h>

#include "facet/abi/shader_abi.h"

namespace facet::runtime {
namespace {

constexpr size_t kPosition = 0, kNormal = 3, kUv0 = 6, kUv1 = 8, kTangent = 14;

struct Primitive {
  Mesh* mesh;
  size_t firstIndex;
  size_t uvOffset;
  std::vector<std::array<float, 4>> corners;  // the tangent MikkTSpace gives each corner

  const float* vertex(int face, int corner) const {
    const uint32_t index = mesh->indices[firstIndex + size_t(face) * 3 + size_t(corner)];
    return &mesh->vertices[size_t(index) * abi::kVertexFloats];
  }
};

Primitive& primitiveOf(const SMikkTSpaceContext* context) { return *static_cast<Primitive*>(context->m_pUserData); }

int faces(const SMikkTSpaceContext* context) {
  const Primitive& p = primitiveOf(context);
  return int((p.mesh->indices.size() - p.firstIndex) / 3);
}

int cornersOfFace(const SMikkTSpaceContext*, const int) { return 3; }

void position(const SMikkTSpaceContext* context, float out[], const int face, const int corner) {
  std::memcpy(out, primitiveOf(context).vertex(face, corner) + kPosition, 3 * sizeof(float));
}

void normal(const SMikkTSpaceContext* context, float out[], const int face, const int corner) {
  std::memcpy(out, primitiveOf(context).vertex(face, corner) + kNormal, 3 * sizeof(float));
}

// glTF's v runs down the image and its normal maps' green up it (glTF 2.0 §3.9.3: +Y is up), so
// MikkTSpace is given v flipped: its bitangent (along +t) then points up the image, as green
// does, the convention of the tangents exporters such as Blender's write into glTF files.
void texCoord(const SMikkTSpaceContext* context, float out[], const int face, const int corner) {
  const Primitive& p = primitiveOf(context);
  const float* uv = p.vertex(face, corner) + p.uvOffset;
  out[0] = uv[0];
  out[1] = -uv[1];
}

void setTangent(const SMikkTSpaceContext* context, const float tangent[], const float sign, const int face,
                const int corner) {
  primitiveOf(context).corners[size_t(face) * 3 + size_t(corner)] = {tangent[0], tangent[1], tangent[2], sign};
}

}  // namespace

bool generateMikkTSpaceTangents(Mesh* mesh, size_t firstVertex, size_t firstIndex, int uvSet) {
  Primitive p{mesh, firstIndex, uvSet == 1 ? kUv1 : kUv0, {}};
  p.corners.resize(mesh->indices.size() - firstIndex);
  SMikkTSpaceInterface callbacks{};
  callbacks.m_getNumFaces = faces;
  callbacks.m_getNumVerticesOfFace = cornersOfFace;
  callbacks.m_getPosition = position;
  callbacks.m_getNormal = normal;
  callbacks.m_getTexCoord = texCoord;
  callbacks.m_setTSpaceBasic = setTangent;
  SMikkTSpaceContext context{&callbacks, &p};
  if (!genTangSpaceDefault(&context)) return false;
  // Back to indexed vertices: the first corner of a vertex sets its tangent; a corner wanting
  // another tangent gets a copy of the vertex with it (the copies keyed by vertex and tangent).
  const size_t vertexCount = mesh->vertices.size() / abi::kVertexFloats;
  std::vector<bool> set(vertexCount - firstVertex, false);
  std::map<std::pair<uint32_t, std::array<float, 4>>, uint32_t> copies;
  for (size_t c = 0; c < p.corners.size(); ++c) {
    uint32_t& index = mesh->indices[firstIndex + c];
    const std::array<float, 4>& tangent = p.corners[c];
    float* stored = &mesh->vertices[size_t(index) * abi::kVertexFloats + kTangent];
    if (!set[index - firstVertex]) {
      std::memcpy(stored, tangent.data(), sizeof tangent);
      set[index - firstVertex] = true;
      continue;
    }
    if (std::memcmp(stored, tangent.data(), sizeof tangent) == 0) continue;
    auto [copy, added] = copies.try_emplace({index, tangent}, uint32_t(mesh->vertices.size() / abi::kVertexFloats));
    if (added) {
      std::array<float, abi::kVertexFloats> vertex;
      std::memcpy(vertex.data(), &mesh->vertices[size_t(index) * abi::kVertexFloats], sizeof vertex);
      std::memcpy(&vertex[kTangent], tangent.data(), sizeof tangent);
      mesh->vertices.insert(mesh->vertices.end(), vertex.begin(), vertex.end());
    }
    index = copy->second;
  }
  return true;
}

}  // namespace facet::runtime
