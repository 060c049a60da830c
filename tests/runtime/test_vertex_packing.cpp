// Packed vertices (runtime/vertex_packing.h): the layouts' sizes, each attribute's error against
// the bound the header derives, the rule that keeps fp32 positions, refusals of what must not
// reach a GPU, the vertex-cache reordering, and images of packed meshes against full precision
// on both backends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "facet/package/package.h"
#include "facet/runtime/gltf_mesh.h"
#include "facet/runtime/material.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/mesh_optimize.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/runtime/vertex_packing.h"
#include "facet/scene/scene.h"
#include "test_compile.h"
#include "test_images.h"
#include "test_support.h"

namespace facet::runtime {
namespace {

Vertex vertexAt(const Mesh& mesh, size_t i) {
  Vertex v;
  std::memcpy(static_cast<void*>(&v), mesh.vertices.data() + i * abi::kVertexFloats, sizeof v);
  return v;
}

// What the vertex fetch hands the shader, then the shader's FMA: the GPU's decode, on the CPU.
struct Decoded {
  double position[3], normal[3], tangent[4], uv[2][2], color[4];
};
double snorm(int32_t q, int bits) { return std::max(double(q) / double((1 << (bits - 1)) - 1), -1.0); }
int32_t field(uint32_t word, int shift, int bits) {
  const auto raw = int32_t(word << (32 - shift - bits));
  return raw >> (32 - bits);  // sign-extended
}
Decoded decode(const PackedMesh& p, uint32_t v) {
  Decoded d{};
  const VertexLayoutDesc& layout = vertexLayout(p.layout);
  const auto at = [&](const StreamAttribute& a) {
    return p.streams[a.stream].data() + size_t(v) * layout.strides[a.stream] + a.offset;
  };
  for (const StreamAttribute& a : layout.attributes) {
    const uint8_t* src = at(a);
    double value[4] = {0, 0, 0, 0};
    switch (a.format) {
      case VertexFormat::Float32x2:
      case VertexFormat::Float32x3:
      case VertexFormat::Float32x4: {
        float f[4] = {0, 0, 0, 0};
        std::memcpy(f, src, a.format == VertexFormat::Float32x2 ? 8 : a.format == VertexFormat::Float32x3 ? 12 : 16);
        for (int i = 0; i < 4; ++i) value[i] = f[i];
        break;
      }
      case VertexFormat::Snorm16x4: {
        int16_t q[4];
        std::memcpy(q, src, 8);
        for (int i = 0; i < 4; ++i) value[i] = snorm(q[i], 16);
        break;
      }
      case VertexFormat::Unorm16x2: {
        uint16_t q[2];
        std::memcpy(q, src, 4);
        for (int i = 0; i < 2; ++i) value[i] = q[i] / 65535.0;
        break;
      }
      case VertexFormat::Snorm10x3w2: {
        uint32_t w;
        std::memcpy(&w, src, 4);
        for (int i = 0; i < 3; ++i) value[i] = snorm(field(w, 10 * i, 10), 10);
        value[3] = snorm(field(w, 30, 2), 2);
        break;
      }
      case VertexFormat::Unorm8x4:
        for (int i = 0; i < 4; ++i) value[i] = src[i] / 255.0;
        break;
    }
    switch (a.location) {
      case abi::kAttribPosition:
        for (int i = 0; i < 3; ++i) d.position[i] = value[i] * p.decode.positionScale[i] + p.decode.positionOffset[i];
        break;
      case abi::kAttribNormal: std::copy(value, value + 3, d.normal); break;
      case abi::kAttribTangent: std::copy(value, value + 4, d.tangent); break;
      case abi::kAttribColor: std::copy(value, value + 4, d.color); break;
      default: {
        const int set = a.location == abi::kAttribUv0 ? 0 : 1;
        for (int i = 0; i < 2; ++i)
          d.uv[set][i] = value[i] * p.decode.uvScaleOffset[set][i] + p.decode.uvScaleOffset[set][2 + i];
      }
    }
  }
  return d;
}

double angle(const double* a, const float* b) {
  const double la = std::hypot(a[0], a[1], a[2]), lb = std::hypot(b[0], b[1], b[2]);
  const double c = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

TEST(VertexPacking, PackedVerticesTake28BytesAgainst72) {
  EXPECT_EQ(sizeof(Vertex), 72u);
  PackedMesh packed;
  std::string error;
  ASSERT_TRUE(packMesh(makeSphere(), VertexPacking::Packed, &packed, &error)) << error;
  EXPECT_EQ(packed.layout, VertexLayout::Packed);
  EXPECT_EQ(packed.bytesPerVertex(), 28u);
  EXPECT_LE(packed.bytesPerVertex(), 0.4 * 72);
  EXPECT_EQ(vertexLayout(VertexLayout::Packed).strides[abi::kPositionStream], 8u);
  EXPECT_EQ(vertexLayout(VertexLayout::PackedFloatPositions).strides[abi::kPositionStream], 12u);
  ASSERT_TRUE(packMesh(makeSphere(), VertexPacking::FullPrecision, &packed, &error)) << error;
  EXPECT_EQ(packed.bytesPerVertex(), 72u);
  // Every attribute in its stream: positions alone in stream 0.
  for (VertexLayout layout : {VertexLayout::FullPrecision, VertexLayout::Packed, VertexLayout::PackedFloatPositions})
    for (const StreamAttribute& a : vertexLayout(layout).attributes)
      EXPECT_EQ(a.stream, abi::vertexAttribute(a.location).stream);
}

// Each attribute of the sphere decodes within the bound vertex_packing.h derives.
TEST(VertexPacking, EachAttributeDecodesWithinItsBound) {
  Mesh sphere = makeSphere();
  // Colours and a second UV set that use their ranges.
  for (size_t v = 0; v < sphere.vertices.size() / abi::kVertexFloats; ++v) {
    float* f = &sphere.vertices[v * abi::kVertexFloats];
    f[8] = f[6] * 8 - 3;             // uv1 in [-3, 5]: tiled
    f[10] = f[0] * 0.5f + 0.5f;      // colour r in [0, 1]
    f[13] = float(v % 7) / 6;        // alpha
    f[17] = (v % 2) ? 1.0f : -1.0f;  // tangent sign
  }
  PackedMesh packed;
  std::string error;
  ASSERT_TRUE(packMesh(sphere, VertexPacking::Packed, &packed, &error)) << error;
  ASSERT_EQ(packed.layout, VertexLayout::Packed);
  double position = 0, normal = 0, tangent = 0, uv0 = 0, uv1 = 0, colour = 0;
  for (uint32_t v = 0; v < packed.vertexCount; ++v) {
    const Vertex in = vertexAt(sphere, v);
    const Decoded out = decode(packed, v);
    for (int i = 0; i < 3; ++i) position = std::max(position, std::abs(out.position[i] - in.position[i]));
    normal = std::max(normal, angle(out.normal, in.normal));
    tangent = std::max(tangent, angle(out.tangent, in.tangent));
    EXPECT_EQ(out.tangent[3], in.tangent[3]) << "the bitangent sign is exact";
    for (int i = 0; i < 2; ++i) {
      uv0 = std::max(uv0, std::abs(out.uv[0][i] - in.uv0[i]));
      uv1 = std::max(uv1, std::abs(out.uv[1][i] - in.uv1[i]));
    }
    for (int i = 0; i < 4; ++i) colour = std::max(colour, std::abs(out.color[i] - in.color[i]));
  }
  // extent / 131068 per axis (extent 2), plus fp32 rounding of the scale and the input.
  EXPECT_LE(position, 2.0 / 131068 * 1.001);
  EXPECT_GT(position, 0.0);
  // A 10-bit component moves by at most 1/1022; the direction by at most √3/1022 rad.
  EXPECT_LE(normal, std::sqrt(3.0) / 1022);
  EXPECT_LE(tangent, std::sqrt(3.0) / 1022);
  EXPECT_LE(uv0, 1.0 / 131070 * 1.001);  // extent 1
  EXPECT_LE(uv1, 8.0 / 131070 * 1.001);  // extent 8: 0.25 texel on a 4096-texel texture
  EXPECT_LE(colour, 0.5 / 255 + 1e-9);
  std::printf(
      "sphere, packed: position %.3g (extent 2), normal %.3g rad, tangent %.3g rad, uv0 %.3g, uv1 %.3g "
      "(extent 8), colour %.3g\n",
      position, normal, tangent, uv0, uv1, colour);
}

TEST(VertexPacking, FullPrecisionIsTheMeshsOwnFloats) {
  const Mesh sphere = makeSphere(8, 16);
  PackedMesh packed;
  std::string error;
  ASSERT_TRUE(packMesh(sphere, VertexPacking::FullPrecision, &packed, &error)) << error;
  for (uint32_t v = 0; v < packed.vertexCount; ++v) {
    const Vertex in = vertexAt(sphere, v);
    const Decoded out = decode(packed, v);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(out.position[i], double(in.position[i]));
    for (int i = 0; i < 4; ++i) EXPECT_EQ(out.tangent[i], double(in.tangent[i]));
    EXPECT_EQ(out.uv[1][0], double(in.uv1[0]));
  }
}

// The rule: 16-bit positions when the step is at most the median edge / 512. A mesh whose
// triangles are small against its extent (two 1 cm triangles 10 km apart) keeps fp32.
TEST(VertexPacking, PositionsKeepFp32WhereSixteenBitsWouldMoveThemTooFar) {
  EXPECT_TRUE(sixteenBitPositionsAllowed(2.0, 0.04));
  EXPECT_FALSE(sixteenBitPositionsAllowed(1e4, 0.01));
  EXPECT_TRUE(sixteenBitPositionsAllowed(0.0, 0.0));
  EXPECT_FALSE(sixteenBitPositionsAllowed(INFINITY, 1.0));
  Mesh far;
  for (float x : {0.0f, 1e4f}) {
    Vertex v;
    for (const auto& c : {std::array<float, 2>{0, 0}, {0.01f, 0}, {0, 0.01f}}) {
      v.position[0] = x + c[0];
      v.position[1] = c[1];
      appendVertex(far, v);
    }
  }
  far.indices = {0, 1, 2, 3, 4, 5};
  PackedMesh packed;
  std::string error;
  ASSERT_TRUE(packMesh(far, VertexPacking::Packed, &packed, &error)) << error;
  EXPECT_EQ(packed.layout, VertexLayout::PackedFloatPositions);
  EXPECT_EQ(packed.bytesPerVertex(), 32u);
  EXPECT_EQ(decode(packed, 4).position[0], double(1e4f + 0.01f));
  // Without indices (a non-indexed draw), consecutive vertices are the triangles: the sphere's
  // corners unrolled still pack 16-bit.
  const Mesh indexed = makeSphere(8, 16);
  Mesh unrolled;
  for (uint32_t i : indexed.indices) appendVertex(unrolled, vertexAt(indexed, i));
  ASSERT_TRUE(packMesh(unrolled, VertexPacking::Packed, &packed, &error)) << error;
  EXPECT_EQ(packed.layout, VertexLayout::Packed);
  // A flat mesh (z = 0 everywhere) packs with scale 1 on the flat axis, never 0.
  Mesh flat = makeSphere(4, 8);
  for (size_t v = 0; v < flat.vertices.size(); v += abi::kVertexFloats) flat.vertices[v + 2] = 0.25f;
  ASSERT_TRUE(packMesh(flat, VertexPacking::Packed, &packed, &error)) << error;
  EXPECT_EQ(packed.decode.positionScale[2], 1.0f);
  EXPECT_EQ(decode(packed, 3).position[2], 0.25);
  // An axis spanning less than the smallest normal float is flat too: half of one denormal step
  // rounds to a zero float scale, which checkPackedMesh would refuse (found by fuzz_gltf).
  const size_t uv0 = abi::vertexAttribute(abi::kAttribUv0).offsetFloats;
  for (size_t v = 0; v < flat.vertices.size(); v += abi::kVertexFloats) {
    const bool odd = (v / abi::kVertexFloats) % 2 == 1;
    flat.vertices[v + 2] = odd ? std::numeric_limits<float>::denorm_min() : 0.0f;
    flat.vertices[v + uv0] = odd ? std::numeric_limits<float>::denorm_min() : 0.0f;
  }
  ASSERT_TRUE(packMesh(flat, VertexPacking::Packed, &packed, &error)) << error;
  EXPECT_EQ(packed.decode.positionScale[2], 1.0f);
  EXPECT_EQ(packed.decode.uvScaleOffset[0][0], 1.0f);
  EXPECT_EQ(decode(packed, 3).position[2], 0.0);
}

TEST(VertexPacking, WhatMustNotReachTheGpuIsRefusedWithAMessage) {
  PackedMesh packed;
  std::string error;
  Mesh nan = makeSphere(4, 8);
  nan.vertices[5 * abi::kVertexFloats + 7] = std::nanf("");  // vertex 5, uv0.y
  EXPECT_FALSE(packMesh(nan, VertexPacking::Packed, &packed, &error));
  EXPECT_EQ(error, "mesh vertex 5: uv0 is not finite");
  EXPECT_FALSE(packMesh(nan, VertexPacking::FullPrecision, &packed, &error));
  Mesh wide = makeSphere(4, 8);
  wide.vertices[6] = -3e38f;
  wide.vertices[abi::kVertexFloats + 6] = 3e38f;  // uv0.x spans more than a float
  EXPECT_FALSE(packMesh(wide, VertexPacking::Packed, &packed, &error));
  EXPECT_NE(error.find("uv0 spans"), std::string::npos) << error;
  EXPECT_TRUE(packMesh(wide, VertexPacking::FullPrecision, &packed, &error)) << error;
  Mesh partial = makeSphere(4, 8);
  partial.vertices.pop_back();
  EXPECT_FALSE(packMesh(partial, VertexPacking::Packed, &packed, &error));
  EXPECT_NE(error.find("not a whole number of 18-float vertices"), std::string::npos) << error;

  // A packed mesh with a zero or non-finite decode, or streams of the wrong size.
  PackedMesh good;
  ASSERT_TRUE(packMesh(makeSphere(4, 8), VertexPacking::Packed, &good, &error)) << error;
  ASSERT_TRUE(checkPackedMesh(good, &error)) << error;
  PackedMesh damaged = good;
  damaged.decode.positionScale[1] = 0;
  EXPECT_FALSE(checkPackedMesh(damaged, &error));
  EXPECT_NE(error.find("position scale 0.000000 / offset"), std::string::npos) << error;
  EXPECT_NE(error.find("zero or not finite"), std::string::npos) << error;
  damaged = good;
  damaged.decode.positionOffset[0] = INFINITY;
  EXPECT_FALSE(checkPackedMesh(damaged, &error));
  damaged = good;
  damaged.decode.uvScaleOffset[1][0] = std::nanf("");
  EXPECT_FALSE(checkPackedMesh(damaged, &error));
  EXPECT_NE(error.find("uv1 scale or offset is zero or not finite"), std::string::npos) << error;
  damaged = good;
  damaged.streams[abi::kAttributeStream].pop_back();
  EXPECT_FALSE(checkPackedMesh(damaged, &error));
  EXPECT_NE(error.find("stream 1 holds"), std::string::npos) << error;
}

// The example glTF mesh (a torus in latitude/longitude order, like the sphere): ACMR down.
TEST(VertexPacking, ExampleGltfMeshIsReorderedForTheVertexCache) {
  std::string error;
  auto torus = loadGltfMesh(test::examplePath("scenes/meshes/torus.gltf"), &error);
  ASSERT_TRUE(torus) << error;
  const double before = averageCacheMissRatio(*torus);
  const size_t vertices = torus->vertices.size();
  optimizeMesh(&*torus);
  const double after = averageCacheMissRatio(*torus);
  std::printf("torus.gltf ACMR (16-entry FIFO): %.3f before, %.3f after\n", before, after);
  EXPECT_LT(after, before * 0.9);
  EXPECT_EQ(torus->vertices.size(), vertices);  // every vertex is used: none dropped
}

// Optimised for the post-transform cache: ACMR down, the same triangles.
TEST(VertexPacking, SphereIsReorderedForTheVertexCache) {
  Mesh sphere = makeSphere();
  const double before = averageCacheMissRatio(sphere);
  Mesh optimised = sphere;
  optimizeMesh(&optimised);
  const double after = averageCacheMissRatio(optimised);
  std::printf("sphere ACMR (16-entry FIFO): %.3f before, %.3f after\n", before, after);
  EXPECT_LT(after, before * 0.9);
  ASSERT_EQ(optimised.indices.size(), sphere.indices.size());
  // Same triangles (as sets of corner positions, rotation of the corners allowed).
  const auto key = [](const Mesh& m, size_t t) {
    std::array<std::array<float, 3>, 3> corners;
    for (int c = 0; c < 3; ++c)
      std::memcpy(corners[size_t(c)].data(), &m.vertices[m.indices[t + size_t(c)] * abi::kVertexFloats], 12);
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    return corners;
  };
  std::vector<std::array<std::array<float, 3>, 3>> a, b;
  for (size_t t = 0; t < sphere.indices.size(); t += 3) {
    a.push_back(key(sphere, t));
    b.push_back(key(optimised, t));
  }
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
  // The backends refuse a malformed mesh; the optimiser leaves it for them to.
  Mesh bad = sphere;
  bad.indices.back() = 1u << 30;
  const Mesh copy = bad;
  optimizeMesh(&bad);
  EXPECT_EQ(bad.indices, copy.indices);
}

struct Renders {
  std::string error;
  std::unique_ptr<RenderBackend> backend[2][2];  // [vulkan, gl][packed, full precision]
};

Renders& renderers() {
  static Renders r = [] {
    Renders out;
    for (int p = 0; p < 2; ++p) {
      const VertexPacking packing = p == 0 ? VertexPacking::Packed : VertexPacking::FullPrecision;
      VulkanOptions vk;
      vk.validation = true;
      vk.vertexPacking = packing;
      out.backend[0][p] = createVulkanBackend(vk, &out.error);
      if (!out.backend[0][p]) return out;
      GlOptions gl;
      gl.vertexPacking = packing;
      out.backend[1][p] = createGlBackend(gl, &out.error);
      if (!out.backend[1][p]) return out;
    }
    return out;
  }();
  return r;
}

const std::string& examplePackages() {
  static const std::string dir = [] {
    compiler::BuildOptions build;
    build.tiers = {permutations::Tier::High};
    build.pointLightCounts = {0, 1, 2, 4};
    build.shadowCascadeCounts = {0, 4};  // yard.json's sun casts, with the default 4 cascades
    return test::writeExamplePackages("packed-vertex-packages", build);
  }();
  return dir;
}

// Every example scene, packed against full precision, on both APIs: PSNR of the 8-bit images.
TEST(VertexPacking, ExampleScenesPackedMatchFullPrecisionAbove50Db) {
  Renders& r = renderers();
  ASSERT_TRUE(r.error.empty()) << r.error;
  std::vector<std::string> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(test::examplePath("scenes")))
    if (entry.path().extension() == ".json") scenes.push_back(entry.path().string());
  std::sort(scenes.begin(), scenes.end());
  ASSERT_GE(scenes.size(), 8u);
  for (const std::string& path : scenes) {
    std::string error;
    auto scene = loadScene(path, &error);
    ASSERT_TRUE(scene) << error;
    auto frame = SceneFrame::prepare(*scene, examplePackages(), &error);
    ASSERT_TRUE(frame) << error;
    // GL does not draw the shadow pass (docs/shadows.md): a casting sun is Vulkan's alone.
    const int apis = scene->sun && scene->sun->castShadows ? 1 : 2;
    for (int api = 0; api < apis; ++api) {
      FrameResult packed, full;
      ASSERT_TRUE(r.backend[api][0]->render(frame->frame(), &packed, &error)) << path << ": " << error;
      ASSERT_TRUE(r.backend[api][1]->render(frame->frame(), &full, &error)) << path << ": " << error;
      const double db = test::psnr(full.ldr, packed.ldr);
      std::printf("%s %s: PSNR packed against full precision %.1f dB\n", std::filesystem::path(path).filename().c_str(),
                  api == 0 ? "vulkan" : "gl", db);
      EXPECT_GE(db, 50.0) << path << (api == 0 ? " vulkan" : " gl");
      EXPECT_TRUE(r.backend[api][0]->validationErrors().empty());
    }
  }
}

// A mesh that cannot be packed fails the frame with the packing's message, naming the draw.
TEST(VertexPacking, BackendsRefuseAMeshThatCannotBePacked) {
  Renders& r = renderers();
  ASSERT_TRUE(r.error.empty()) << r.error;
  std::string error;
  auto scene = loadScene(test::examplePath("scenes/sphere.json"), &error);
  ASSERT_TRUE(scene) << error;
  auto frame = SceneFrame::prepare(*scene, examplePackages(), &error);
  ASSERT_TRUE(frame) << error;
  Mesh bad = makeSphere(4, 8);
  bad.vertices[0] = INFINITY;
  FrameDesc desc = frame->frame();
  for (DrawItem& draw : desc.draws) draw.mesh = &bad;
  for (int api = 0; api < 2; ++api) {
    FrameResult out;
    EXPECT_FALSE(r.backend[api][0]->render(desc, &out, &error));
    EXPECT_NE(error.find("mesh vertex 0: position is not finite"), std::string::npos) << error;
  }
}

// Formats 1.5 and 1.6: packages from before 1.5 read one fp32 stream without a decode, from
// before 1.6 their transform from ObjectUniforms. The runtime refuses to draw them with the
// message that says how to rebuild (the mechanism of lit packages before 1.4).
TEST(PackedVertexFormat, AnOlderPackageIsRefusedWithARebuildMessage) {
  auto built = test::buildFile(test::examplePath("materials/red_plastic.mat"), [] {
    compiler::BuildOptions o;
    o.tiers = {permutations::Tier::High};
    return o;
  }());
  ASSERT_TRUE(built);
  const std::string dir = test::scratchDir("packed-vertex-format");
  const auto save = [&](const package::Package& p, const std::string& name) {
    const std::vector<uint8_t> bytes = package::write(p);
    std::ofstream(dir + "/" + name, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return dir + "/" + name;
  };
  std::string error;
  EXPECT_TRUE(built->package.packedVertices);
  EXPECT_TRUE(LoadedMaterial::load(save(built->package, "current.matpkg"), &error)) << error;
  EXPECT_TRUE(built->package.instanceTransforms);
  package::Package older = built->package;
  older.instanceTransforms = false;  // as the 1.5 writer stamped it
  std::string path = save(older, "older15.matpkg");
  EXPECT_FALSE(LoadedMaterial::load(path, &error));
  EXPECT_NE(error.find(path + ": package format 1.5 reads its transform from ObjectUniforms, which this runtime no "
                              "longer provides (per-instance transforms since format 1.6); rebuild it with this "
                              "release's compiler: matc compile MATERIAL.mat -o PACKAGE.matpkg"),
            std::string::npos)
      << error;
  older.packedVertices = false;  // as the 1.4 writer stamped it
  path = save(older, "older.matpkg");
  EXPECT_FALSE(LoadedMaterial::load(path, &error));
  EXPECT_NE(error.find(path + ": package format 1.4 reads one interleaved fp32 vertex stream, which this runtime no "
                              "longer provides (two packed streams since format 1.5); rebuild it with this release's "
                              "compiler: matc compile MATERIAL.mat -o PACKAGE.matpkg"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace facet::runtime
