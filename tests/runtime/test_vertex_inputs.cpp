// The optional vertex inputs (uv1, colour, the tangent frame behind normal maps) and the view
// direction reach the surface program with the values the mesh and camera give, on both backends.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "facet/runtime/mesh.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using facet::runtime::FrameResult;
using facet::runtime::Mesh;
using facet::runtime::Vertex;

// One object 6 units in front of the camera, lit by a low sun from the right so that tilting
// the normal about the y axis changes n·l a lot.
const char* kScene =
    R"({"width": 64, "height": 64, "sun": {"direction": [-0.8, -0.1, -0.6]}, "sky": {"luminance": 2000},
  "camera": {"position": [0, 0, 6], "fovY": 30}, "objects": [{"material": "%s"}]})";

// A unit quad facing +z (towards the camera), wound counter-clockwise, every vertex alike but for
// its position.
Mesh quad(Vertex v) {
  Mesh mesh;
  const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (const auto& c : corners) {
    v.position[0] = c[0];
    v.position[1] = c[1];
    v.position[2] = 0;
    facet::runtime::appendVertex(mesh, v);
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

struct Backends {
  std::string error;
  std::unique_ptr<facet::runtime::RenderBackend> vulkan, gl;
};

Backends& backends() {
  static Backends b = [] {
    Backends out;
    out.vulkan = facet::runtime::createVulkanBackend({true}, &out.error);
    if (out.vulkan) out.gl = facet::runtime::createGlBackend(&out.error);
    return out;
  }();
  return b;
}

// Renders material `name` (from `packages`) on `mesh` with the given backend.
bool render(const std::string& packages, const std::string& name, const Mesh& mesh,
            facet::runtime::RenderBackend& backend, FrameResult* out, std::string* error) {
  char json[512];
  std::snprintf(json, sizeof json, kScene, name.c_str());
  auto scene = facet::runtime::parseScene(facet::test::examplePath("scenes/inline.json"), json, error);
  if (!scene) return false;
  auto prepared = facet::runtime::SceneFrame::prepare(*scene, packages, error);
  if (!prepared) return false;
  facet::runtime::FrameDesc frame = prepared->frame();
  for (auto& draw : frame.draws) draw.mesh = &mesh;
  return backend.render(frame, out, error);
}

// The largest difference between two HDR images relative to the brightest value in `a`.
double maxRelativeHdrDifference(const FrameResult& a, const FrameResult& b) {
  double peak = 0, diff = 0;
  for (size_t i = 0; i < a.hdr.size() && i < b.hdr.size(); ++i) {
    peak = std::max(peak, double(std::abs(a.hdr[i])));
    diff = std::max(diff, double(std::abs(a.hdr[i] - b.hdr[i])));
  }
  return a.hdr.size() == b.hdr.size() && peak > 0 ? diff / peak : 1.0;
}

std::array<float, 4> centre(const FrameResult& r) {
  size_t i = (size_t(r.height / 2) * r.width + r.width / 2) * 4;
  return {r.hdr[i], r.hdr[i + 1], r.hdr[i + 2], r.hdr[i + 3]};
}

class VertexInputs : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    ASSERT_EQ(backends().error, "");
    backend_ = std::string(GetParam()) == "vulkan" ? backends().vulkan.get() : backends().gl.get();
  }
  void TearDown() override { EXPECT_TRUE(backend_->validationErrors().empty()); }
  facet::runtime::RenderBackend* backend_ = nullptr;
};

}  // namespace

// A tangent-space normal n_t on a quad with tangent t, normal n and handedness w shades exactly
// like geometry whose vertex normal is x·t + y·w·(n × t) + z·n: the tangent frame is MikkTSpace's.
// Both handedness signs are checked, since a flipped sign mirrors every normal map's green axis.
TEST_P(VertexInputs, NormalOutputShadesLikeGeometryWithThatNormal) {
  const std::string packages = facet::test::writePackagesFromTexts(
      "normal-output", {"material tilted { surface { normal = vec3(0.6, 0.48, 0.64) roughness = 0.4 } }",
                        "material plain { surface { roughness = 0.4 } }"});
  struct Case {
    float w;
    Vertex geometry;  // vertex normal the tilted normal must equal
  };
  // t = +x, n = +z: n × t = +y. With w = +1 the world normal is (0.6, 0.48, 0.64); w = −1 flips y.
  const Case cases[] = {{+1.0f, Vertex{{}, {0.6f, 0.48f, 0.64f}}}, {-1.0f, Vertex{{}, {0.6f, -0.48f, 0.64f}}}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.w);
    Vertex mapped;
    mapped.tangent[3] = c.w;
    Mesh mappedQuad = quad(mapped), geometryQuad = quad(c.geometry);
    FrameResult a, b, flat;
    std::string error;
    ASSERT_TRUE(render(packages, "tilted", mappedQuad, *backend_, &a, &error)) << error;
    ASSERT_TRUE(render(packages, "plain", geometryQuad, *backend_, &b, &error)) << error;
    ASSERT_TRUE(render(packages, "plain", mappedQuad, *backend_, &flat, &error)) << error;
    // Same maths on the same values but for the normal's construction (one normalize vs two):
    // fp16 storage of the HDR target is the only expected difference.
    EXPECT_LE(maxRelativeHdrDifference(b, a), 0.01);
    // And the tilt is visible: the untilted quad differs by about 20 % of the peak (measured
    // 0.198 for w = −1 on both backends), so the check above cannot pass by ignoring the normal.
    EXPECT_GE(maxRelativeHdrDifference(b, flat), 0.1);
  }
}

// A texture(normal) decodes RGB to xyz = rgb · 255/127 − 128/127: a 1×1 normal map shades like
// the same normal written as a constant (texel 204 → 76/127, 128 → exactly 0).
TEST_P(VertexInputs, NormalMapTexelDecodesToTheTangentSpaceNormal) {
  const std::string packages = facet::test::writePackagesFromTexts(
      "normal-map", {"material mapped { param bumps: texture(normal) = vec4(0.8, 0.5, 0.8, 1.0)\n"
                     " surface { normal = sample(params.bumps, vertex.uv0) roughness = 0.4 } }",
                     "material constant { surface { normal = (vec3(204.0, 128.0, 204.0) - 128.0) / 127.0"
                     " roughness = 0.4 } }"});
  Mesh mesh = quad(Vertex{});
  FrameResult a, b;
  std::string error;
  ASSERT_TRUE(render(packages, "mapped", mesh, *backend_, &a, &error)) << error;
  ASSERT_TRUE(render(packages, "constant", mesh, *backend_, &b, &error)) << error;
  EXPECT_LE(maxRelativeHdrDifference(b, a), 0.01);
}

// On a sphere, a flat normal (0, 0, 1) through the analytic tangent frame is the interpolated
// normal itself: the image matches the sphere without a normal output.
TEST_P(VertexInputs, FlatNormalOnTheSphereChangesNothing) {
  const std::string packages = facet::test::writePackagesFromTexts(
      "flat-normal", {"material flat { surface { normal = vec3(0.0, 0.0, 1.0) roughness = 0.3 } }",
                      "material none { surface { roughness = 0.3 } }"});
  Mesh sphere = facet::runtime::makeSphere(32, 64);
  FrameResult a, b;
  std::string error;
  ASSERT_TRUE(render(packages, "flat", sphere, *backend_, &a, &error)) << error;
  ASSERT_TRUE(render(packages, "none", sphere, *backend_, &b, &error)) << error;
  EXPECT_LE(maxRelativeHdrDifference(b, a), 0.01);
}

// Unlit output is the surface's colour as written, so the centre pixel shows the inputs directly.
TEST_P(VertexInputs, ColourUv1AndViewDirectionReachTheSurface) {
  const std::string packages = facet::test::writePackagesFromTexts(
      "vertex-values", {"material colour { shading unlit surface { baseColor = vertex.color.rgb * vertex.color.a } }",
                        "material uv { shading unlit surface { baseColor = vec3(vertex.uv1, 0.25) } }",
                        "material view { shading unlit surface { baseColor = vertex.viewDirection * 0.5 + 0.5 } }"});
  Vertex v;
  v.color[0] = 0.25f, v.color[1] = 0.5f, v.color[2] = 1.0f, v.color[3] = 0.5f;
  v.uv1[0] = 0.375f, v.uv1[1] = 0.75f;
  Mesh mesh = quad(v);
  struct Case {
    const char* material;
    std::array<float, 3> expected;
  };
  // The camera sits on +z looking at the quad's centre: the view direction there is (0, 0, 1).
  const Case cases[] = {
      {"colour", {0.125f, 0.25f, 0.5f}}, {"uv", {0.375f, 0.75f, 0.25f}}, {"view", {0.5f, 0.5f, 1.0f}}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.material);
    FrameResult r;
    std::string error;
    ASSERT_TRUE(render(packages, c.material, mesh, *backend_, &r, &error)) << error;
    auto got = centre(r);
    // fp16 target: 11 significant bits; the view direction is off-axis by half a pixel (< 0.01).
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[size_t(i)], c.expected[size_t(i)], 0.01) << "channel " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, VertexInputs, ::testing::Values("vulkan", "gl"),
                         [](const auto& param) { return std::string(param.param); });
