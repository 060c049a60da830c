// A Mesh (the fp32 authoring form apps and loaders fill) packed into the two vertex streams of
// shader_abi.h: positions in stream 0, every other attribute in stream 1. Both backends call
// packMesh() when they upload a mesh, so apps, loaders and built-in meshes never see the packed
// form. The formats are pipeline state (Vulkan vertex input, GL vertex array): every shader
// reads the same `in highp vecN` whatever the layout, and decodes positions and UVs with one FMA
// from ObjectUniforms (applyVertexDecode).
//
// Packed layout (VertexPacking::Packed, 28 bytes a vertex against fp32's 72):
//   stream 0  position  R16G16B16A16_SNORM, 8 B: q = round((p − offset) / scale · 32767), w = 0.
//             The step is extent / 65534 per axis. Chosen where the error allows (below), else
//             R32G32B32_SFLOAT, 12 B (VertexLayout::PackedFloatPositions, 32 bytes a vertex).
//   stream 1  normal    A2B10G10R10_SNORM_PACK32 (GL_INT_2_10_10_10_REV, normalized), 4 B
//             tangent   the same, w = the bitangent sign in the 2-bit field (−1 or +1 exactly), 4 B
//             uv0, uv1  R16G16_UNORM with a per-mesh scale and offset (the UV set's bounds), 4 B each
//             colour    R8G8B8A8_UNORM, 4 B (linear RGBA in [0, 1], clamped)
//
// Why these (docs/runtime.md, "Packed vertices", has the measured figures):
// - Positions: 16 bits over the mesh's bounds move a vertex by at most extent / 131068 per axis.
//   The rule that decides: the step (extent / 65534 on the widest axis) must be at most the
//   median edge length / 512, i.e. the error is at most 2^-10 of a typical edge, so an edge tilts
//   by at most about 2^-10 rad — no more than the 10-bit normals' own quantisation (1/1022 per
//   component). A mesh whose detail is fine against its extent (a terrain, a level) keeps fp32
//   positions. The median, not the shortest edge, so that a few slivers (a sphere's pole
//   triangles) do not force fp32 on a whole mesh.
// - Normals and tangents: 10:10:10:2 SNORM is decoded by the vertex fetch hardware (no shader
//   instruction; Vulkan and GLES 3.0 map q to max(q / 511, −1), so the 2-bit w holds ±1
//   exactly). Its error is at most 1/1022 per component before the shader's normalize: 1.5e-3
//   rad (0.086°) on the sphere's normals. Octahedral 16-bit would be 25 times finer (6.0e-5 rad)
//   but costs a fold, a select and a normalize per vertex in the shader; at 10 bits every
//   example scene stays above 58 dB PSNR against fp32 (docs/runtime.md), so the fetch unit does
//   the decode.
// - UVs: 16-bit normalized with the UV set's bounds moves a UV by at most extent / 131070, i.e.
//   T · extent / 131070 texels on a T-texel texture (0.03 texel for [0, 1] on 4096 texels);
//   half floats would move a UV in [0.5, 1) by up to 2^-12 (a whole texel on 4096 texels) and
//   lose more on tiled UVs. The decode is one FMA.
// - Colours: unorm8, the precision of the 8-bit textures they multiply.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "facet/abi/shader_abi.h"
#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// A stream attribute's format in GPU memory. The shader reads each as float vecN.
enum class VertexFormat : uint8_t {
  Float32x2,
  Float32x3,
  Float32x4,
  Snorm16x4,    // VK_FORMAT_R16G16B16A16_SNORM; GL_SHORT ×4 normalized
  Unorm16x2,    // VK_FORMAT_R16G16_UNORM; GL_UNSIGNED_SHORT ×2 normalized
  Snorm10x3w2,  // VK_FORMAT_A2B10G10R10_SNORM_PACK32 (x in bits 0..9); GL_INT_2_10_10_10_REV normalized
  Unorm8x4,     // VK_FORMAT_R8G8B8A8_UNORM; GL_UNSIGNED_BYTE ×4 normalized
};

// The layouts a packed mesh can have; a Vulkan pipeline is built per layout it draws.
enum class VertexLayout : uint8_t {
  FullPrecision,         // VertexPacking::FullPrecision
  Packed,                // 16-bit positions
  PackedFloatPositions,  // fp32 positions (the error did not allow 16 bits), the rest packed
};

struct StreamAttribute {
  uint32_t location;  // abi::kAttrib*
  uint32_t stream;    // abi::kPositionStream or abi::kAttributeStream
  VertexFormat format;
  uint32_t offset;  // bytes from the start of a vertex in its stream
};

struct VertexLayoutDesc {
  uint32_t strides[abi::kVertexStreams];
  StreamAttribute attributes[std::size(abi::kVertexAttributes)];  // in kVertexAttributes' order
};
const VertexLayoutDesc& vertexLayout(VertexLayout layout);
const char* toString(VertexLayout layout);

// What the shader needs to decode a packed mesh (ObjectUniforms' last four vec4s).
struct VertexDecode {
  float positionScale[3] = {1, 1, 1};
  float positionOffset[3] = {0, 0, 0};
  float uvScaleOffset[2][4] = {{1, 1, 0, 0}, {1, 1, 0, 0}};  // uv0, uv1: xy scale, zw offset
};

struct PackedMesh {
  VertexLayout layout = VertexLayout::FullPrecision;
  uint32_t vertexCount = 0;
  std::vector<uint8_t> streams[abi::kVertexStreams];  // vertexCount × stride bytes each
  VertexDecode decode;

  uint32_t bytesPerVertex() const;
};

// Packs the mesh's vertices (indices are left to the caller). False with *error for a mesh the
// GPU must not get: not a whole number of vertices, a component that is not finite, or UVs whose
// bounds are too far apart for a finite scale. Deterministic: the same mesh packs to the same bytes.
bool packMesh(const Mesh& mesh, VertexPacking packing, PackedMesh* out, std::string* error);

// What a backend checks before it uploads a packed mesh: sizes that match the layout and a
// decode whose scales are finite and non-zero (a zero scale would collapse the mesh, a NaN would
// draw nothing at all, with no message).
bool checkPackedMesh(const PackedMesh& packed, std::string* error);

// The ObjectUniforms a draw of the packed mesh binds: the mesh's decode.
abi::ObjectUniforms objectUniforms(const VertexDecode& decode);

// The rule above: whether a mesh with this position extent (widest axis) and median edge
// length gets 16-bit positions. Exposed for tests and documentation.
bool sixteenBitPositionsAllowed(double widestExtent, double medianEdge);

}  // namespace facet::runtime
