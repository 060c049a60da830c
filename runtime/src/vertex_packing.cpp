#include "facet/runtime/vertex_packing.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace facet::runtime {
namespace {

using abi::kAttributeStream;
using abi::kPositionStream;

// kVertexAttributes' order: position, normal, uv0, uv1, colour, tangent.
constexpr VertexLayoutDesc kFullPrecision{{12, 60},
                                          {{abi::kAttribPosition, kPositionStream, VertexFormat::Float32x3, 0},
                                           {abi::kAttribNormal, kAttributeStream, VertexFormat::Float32x3, 0},
                                           {abi::kAttribUv0, kAttributeStream, VertexFormat::Float32x2, 12},
                                           {abi::kAttribUv1, kAttributeStream, VertexFormat::Float32x2, 20},
                                           {abi::kAttribColor, kAttributeStream, VertexFormat::Float32x4, 28},
                                           {abi::kAttribTangent, kAttributeStream, VertexFormat::Float32x4, 44}}};
constexpr uint32_t kPackedAttributeStride = 20;
constexpr StreamAttribute kPackedAttributes[] = {{abi::kAttribNormal, kAttributeStream, VertexFormat::Snorm10x3w2, 0},
                                                 {abi::kAttribUv0, kAttributeStream, VertexFormat::Unorm16x2, 8},
                                                 {abi::kAttribUv1, kAttributeStream, VertexFormat::Unorm16x2, 12},
                                                 {abi::kAttribColor, kAttributeStream, VertexFormat::Unorm8x4, 16},
                                                 {abi::kAttribTangent, kAttributeStream, VertexFormat::Snorm10x3w2, 4}};
// The packed layouts: `position` in stream 0 (`positionBytes` a vertex), the rest as above.
constexpr VertexLayoutDesc packedLayout(VertexFormat position, uint32_t positionBytes) {
  return {{positionBytes, kPackedAttributeStride},
          {{abi::kAttribPosition, kPositionStream, position, 0},
           kPackedAttributes[0],
           kPackedAttributes[1],
           kPackedAttributes[2],
           kPackedAttributes[3],
           kPackedAttributes[4]}};
}
constexpr VertexLayoutDesc kPacked = packedLayout(VertexFormat::Snorm16x4, 8);
constexpr VertexLayoutDesc kPackedFloatPositions = packedLayout(VertexFormat::Float32x3, 12);

constexpr double kSnorm16 = 32767.0;
constexpr double kUnorm16 = 65535.0;
constexpr double kSnorm10 = 511.0;

const char* attributeName(size_t floatIndex) {
  for (const abi::VertexAttribute& a : abi::kVertexAttributes)
    if (floatIndex >= a.offsetFloats && floatIndex < a.offsetFloats + a.components) return a.name.data();
  return "?";
}

void store(std::vector<uint8_t>& bytes, size_t at, const void* value, size_t size) {
  std::memcpy(bytes.data() + at, value, size);
}

// Signed 10:10:10:2, x in the low bits; each field two's complement. Decoded as
// max(q / (2^(b−1) − 1), −1) (Vulkan and GLES 3.0 alike), so ±1 are exact in every field.
uint32_t packSnorm10x3w2(const float* v, float w) {
  uint32_t packed = 0;
  for (int i = 0; i < 3; ++i) {
    const auto q = int32_t(std::lround(std::clamp(double(v[i]), -1.0, 1.0) * kSnorm10));
    packed |= (uint32_t(q) & 0x3ffu) << (10 * i);
  }
  const int32_t sign = w < 0 ? -1 : w > 0 ? 1 : 0;
  return packed | (uint32_t(sign) & 0x3u) << 30;
}

// The median of the mesh's non-degenerate edge lengths; 0 when it has none. A mesh without
// indices is drawn as a triangle list of its vertices (Vulkan's non-indexed draw).
double medianEdgeLength(const Mesh& mesh) {
  std::vector<double> lengths;
  const auto position = [&](uint32_t v) { return &mesh.vertices[size_t(v) * abi::kVertexFloats]; };
  const size_t vertexCount = mesh.vertices.size() / abi::kVertexFloats;
  const size_t corners = mesh.indices.empty() ? vertexCount : mesh.indices.size();
  const auto corner = [&](size_t i) { return mesh.indices.empty() ? uint32_t(i) : mesh.indices[i]; };
  lengths.reserve(corners);
  for (size_t t = 0; t + 2 < corners; t += 3) {
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = corner(t + size_t(e)), b = corner(t + size_t((e + 1) % 3));
      if (a >= vertexCount || b >= vertexCount) continue;  // the backend refuses the mesh
      const float *p = position(a), *q = position(b);
      const double length = std::hypot(double(p[0]) - q[0], double(p[1]) - q[1], double(p[2]) - q[2]);
      if (length > 0 && std::isfinite(length)) lengths.push_back(length);
    }
  }
  if (lengths.empty()) return 0;
  auto middle = lengths.begin() + std::ptrdiff_t(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

// The bounds of `components` floats at `offset` of every vertex, as a centre and half extent.
void bounds(const Mesh& mesh, size_t offset, int components, double* low, double* high) {
  for (int c = 0; c < components; ++c) {
    low[c] = INFINITY;
    high[c] = -INFINITY;
  }
  for (size_t v = 0; v < mesh.vertices.size(); v += abi::kVertexFloats) {
    for (int c = 0; c < components; ++c) {
      low[c] = std::min(low[c], double(mesh.vertices[v + offset + size_t(c)]));
      high[c] = std::max(high[c], double(mesh.vertices[v + offset + size_t(c)]));
    }
  }
}

// The float scale of an axis whose values span `extent` (finite, >= 0). A flat axis keeps scale 1
// (every q is 0): a zero scale is what checkPackedMesh refuses. So does an extent under the
// smallest normal float, 2^-126: it is zero as a float or a denormal, which GPUs that flush
// denormals read as zero; on that axis every vertex then decodes to the offset.
float quantizationScale(double extent) {
  return extent >= double(std::numeric_limits<float>::min()) ? float(extent) : 1.0f;
}

void packPositions16(const Mesh& mesh, PackedMesh* out) {
  double low[3], high[3];
  bounds(mesh, 0, 3, low, high);
  for (int c = 0; c < 3; ++c) {
    const double half = (high[c] - low[c]) / 2;
    out->decode.positionScale[c] = quantizationScale(half);
    out->decode.positionOffset[c] = float(low[c] + half);
  }
  std::vector<uint8_t>& bytes = out->streams[kPositionStream];
  for (uint32_t v = 0; v < out->vertexCount; ++v) {
    const float* p = &mesh.vertices[size_t(v) * abi::kVertexFloats];
    int16_t q[4] = {0, 0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      // Against the float scale and offset the shader uses, so rounding them costs nothing more.
      const double unit = (double(p[c]) - out->decode.positionOffset[c]) / out->decode.positionScale[c];
      q[c] = int16_t(std::lround(std::clamp(unit, -1.0, 1.0) * kSnorm16));
    }
    store(bytes, size_t(v) * 8, q, sizeof q);
  }
}

bool packUvs(const Mesh& mesh, int set, PackedMesh* out, std::string* error) {
  const size_t offset = abi::vertexAttribute(set == 0 ? abi::kAttribUv0 : abi::kAttribUv1).offsetFloats;
  const uint32_t at = vertexLayout(out->layout).attributes[2 + set].offset;
  double low[2], high[2];
  bounds(mesh, offset, 2, low, high);
  float* decode = out->decode.uvScaleOffset[set];
  for (int c = 0; c < 2; ++c) {
    const double extent = high[c] - low[c];
    if (!std::isfinite(float(extent))) {
      *error = "uv" + std::to_string(set) + " spans " + std::to_string(low[c]) + " to " + std::to_string(high[c]) +
               ", too far apart to pack with a finite scale";
      return false;
    }
    decode[c] = quantizationScale(extent);
    decode[2 + c] = float(low[c]);
  }
  std::vector<uint8_t>& bytes = out->streams[kAttributeStream];
  for (uint32_t v = 0; v < out->vertexCount; ++v) {
    const float* uv = &mesh.vertices[size_t(v) * abi::kVertexFloats + offset];
    uint16_t q[2];
    for (int c = 0; c < 2; ++c) {
      const double unit = (double(uv[c]) - decode[2 + c]) / decode[c];
      q[c] = uint16_t(std::lround(std::clamp(unit, 0.0, 1.0) * kUnorm16));
    }
    store(bytes, size_t(v) * kPackedAttributeStride + at, q, sizeof q);
  }
  return true;
}

void packDirectionsAndColours(const Mesh& mesh, PackedMesh* out) {
  std::vector<uint8_t>& bytes = out->streams[kAttributeStream];
  const size_t normal = abi::vertexAttribute(abi::kAttribNormal).offsetFloats;
  const size_t tangent = abi::vertexAttribute(abi::kAttribTangent).offsetFloats;
  const size_t colour = abi::vertexAttribute(abi::kAttribColor).offsetFloats;
  for (uint32_t v = 0; v < out->vertexCount; ++v) {
    const float* f = &mesh.vertices[size_t(v) * abi::kVertexFloats];
    const size_t base = size_t(v) * kPackedAttributeStride;
    const uint32_t n = packSnorm10x3w2(f + normal, 0.0f);
    const uint32_t t = packSnorm10x3w2(f + tangent, f[tangent + 3]);
    uint8_t c[4];
    for (int i = 0; i < 4; ++i) c[i] = uint8_t(std::lround(std::clamp(double(f[colour + size_t(i)]), 0.0, 1.0) * 255));
    store(bytes, base + kPackedAttributes[0].offset, &n, 4);
    store(bytes, base + kPackedAttributes[4].offset, &t, 4);
    store(bytes, base + kPackedAttributes[3].offset, c, 4);
  }
}

void packFullPrecision(const Mesh& mesh, PackedMesh* out) {
  std::vector<uint8_t>& positions = out->streams[kPositionStream];
  std::vector<uint8_t>& rest = out->streams[kAttributeStream];
  for (uint32_t v = 0; v < out->vertexCount; ++v) {
    const float* f = &mesh.vertices[size_t(v) * abi::kVertexFloats];
    store(positions, size_t(v) * 12, f, 12);
    store(rest, size_t(v) * 60, f + 3, 60);  // normal, uv0, uv1, colour, tangent: the authoring order
  }
}

}  // namespace

const VertexLayoutDesc& vertexLayout(VertexLayout layout) {
  switch (layout) {
    case VertexLayout::Packed: return kPacked;
    case VertexLayout::PackedFloatPositions: return kPackedFloatPositions;
    case VertexLayout::FullPrecision: break;
  }
  return kFullPrecision;
}

const char* toString(VertexLayout layout) {
  switch (layout) {
    case VertexLayout::Packed: return "packed";
    case VertexLayout::PackedFloatPositions: return "packed, fp32 positions";
    case VertexLayout::FullPrecision: break;
  }
  return "full precision";
}

uint32_t PackedMesh::bytesPerVertex() const {
  const VertexLayoutDesc& desc = vertexLayout(layout);
  return desc.strides[kPositionStream] + desc.strides[kAttributeStream];
}

bool sixteenBitPositionsAllowed(double widestExtent, double medianEdge) {
  if (!std::isfinite(widestExtent)) return false;
  if (widestExtent == 0) return true;  // every vertex at one point: exact
  return widestExtent / 65534.0 <= medianEdge / 512.0;
}

bool packMesh(const Mesh& mesh, VertexPacking packing, PackedMesh* out, std::string* error) {
  if (mesh.vertices.size() % abi::kVertexFloats != 0) {
    *error = "mesh has " + std::to_string(mesh.vertices.size()) + " floats, not a whole number of " +
             std::to_string(abi::kVertexFloats) + "-float vertices (shader_abi.h's vertex layout)";
    return false;
  }
  const size_t vertexCount = mesh.vertices.size() / abi::kVertexFloats;
  if (vertexCount > UINT32_MAX) {
    *error = "mesh has more vertices than 32-bit indices address";
    return false;
  }
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!std::isfinite(mesh.vertices[i])) {
      *error = "mesh vertex " + std::to_string(i / abi::kVertexFloats) + ": " + attributeName(i % abi::kVertexFloats) +
               " is not finite";
      return false;
    }
  }
  PackedMesh packed;
  packed.vertexCount = uint32_t(vertexCount);
  if (packing == VertexPacking::FullPrecision) {
    packed.layout = VertexLayout::FullPrecision;
  } else {
    double low[3], high[3];
    bounds(mesh, 0, 3, low, high);
    double widest = 0;
    for (int c = 0; c < 3; ++c) widest = std::max(widest, high[c] - low[c]);
    packed.layout = vertexCount == 0 || sixteenBitPositionsAllowed(widest, medianEdgeLength(mesh))
                        ? VertexLayout::Packed
                        : VertexLayout::PackedFloatPositions;
  }
  const VertexLayoutDesc& desc = vertexLayout(packed.layout);
  for (uint32_t s = 0; s < abi::kVertexStreams; ++s) packed.streams[s].assign(vertexCount * desc.strides[s], 0);
  switch (packed.layout) {
    case VertexLayout::FullPrecision: packFullPrecision(mesh, &packed); break;
    case VertexLayout::Packed: packPositions16(mesh, &packed); break;
    case VertexLayout::PackedFloatPositions:
      for (uint32_t v = 0; v < packed.vertexCount; ++v)
        store(packed.streams[kPositionStream], size_t(v) * 12, &mesh.vertices[size_t(v) * abi::kVertexFloats], 12);
      break;
  }
  if (packed.layout != VertexLayout::FullPrecision) {
    for (int set = 0; set < 2; ++set)
      if (!packUvs(mesh, set, &packed, error)) return false;
    packDirectionsAndColours(mesh, &packed);
  }
  *out = std::move(packed);
  return checkPackedMesh(*out, error);
}

bool checkPackedMesh(const PackedMesh& packed, std::string* error) {
  const VertexLayoutDesc& desc = vertexLayout(packed.layout);
  for (uint32_t s = 0; s < abi::kVertexStreams; ++s) {
    if (packed.streams[s].size() != size_t(packed.vertexCount) * desc.strides[s]) {
      *error = "packed mesh stream " + std::to_string(s) + " holds " + std::to_string(packed.streams[s].size()) +
               " bytes, not " + std::to_string(packed.vertexCount) + " vertices of " + std::to_string(desc.strides[s]);
      return false;
    }
  }
  const VertexDecode& d = packed.decode;
  const auto bad = [](float v) { return v == 0 || !std::isfinite(v); };
  const auto finite = [](float v) { return std::isfinite(v); };
  for (int c = 0; c < 3; ++c) {
    if (bad(d.positionScale[c]) || !finite(d.positionOffset[c])) {
      *error = "packed mesh position scale " + std::to_string(d.positionScale[c]) + " / offset " +
               std::to_string(d.positionOffset[c]) + " (axis " + std::to_string(c) +
               ") is zero or not finite: the mesh would collapse or vanish";
      return false;
    }
  }
  for (int set = 0; set < 2; ++set) {
    const float* uv = d.uvScaleOffset[set];
    if (bad(uv[0]) || bad(uv[1]) || !finite(uv[2]) || !finite(uv[3])) {
      *error = "packed mesh uv" + std::to_string(set) + " scale or offset is zero or not finite";
      return false;
    }
  }
  return true;
}

abi::ObjectUniforms objectUniforms(const VertexDecode& decode) {
  abi::ObjectUniforms out{};
  for (int c = 0; c < 3; ++c) {
    out.positionScale[c] = decode.positionScale[c];
    out.positionOffset[c] = decode.positionOffset[c];
  }
  out.positionScale[3] = out.positionOffset[3] = 0;
  std::memcpy(out.uv0ScaleOffset, decode.uvScaleOffset[0], sizeof out.uv0ScaleOffset);
  std::memcpy(out.uv1ScaleOffset, decode.uvScaleOffset[1], sizeof out.uv1ScaleOffset);
  return out;
}

}  // namespace facet::runtime
