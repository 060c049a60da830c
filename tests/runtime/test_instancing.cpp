// Instanced draws (shader_abi.h InstanceTransform): objects that differ only in their transform
// are one draw with an instance each, and the image is the one drawn object by object.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "facet/runtime/material_instance.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "test_compile.h"

namespace facet::runtime {
namespace {

// Lit spheres of one material: rotated, non-uniformly scaled (the normal's transform is the
// cofactor matrix in the shader) and two parameter sets; two transparent ones, which stay one
// draw each, sorted far to near.
const char* kScene = R"({"width": 96, "height": 64, "tier": "high",
  "camera": {"position": [0, 0.5, 6], "target": [0, 0, 0], "fovY": 50},
  "sun": {"direction": [-0.4, -0.55, -0.73], "illuminance": 110000},
  "sky": {"luminance": 6000},
  "objects": [
    {"mesh": "sphere", "material": "plastic", "position": [-2, 0, 0], "scale": [0.5, 0.9, 0.6], "rotation": [20, 30, 0]},
    {"mesh": "sphere", "material": "plastic", "position": [0, 0, 0], "radius": 0.7},
    {"mesh": "box", "material": "plastic", "position": [2, 0, 0], "scale": [0.4, 1.2, 0.7], "rotation": [10, 50, 25]},
    {"mesh": "sphere", "material": "plastic", "position": [-1, 1.2, -1], "radius": 0.4, "params": {"roughness": 0.8}},
    {"mesh": "sphere", "material": "plastic", "position": [1, 1.2, -1], "scale": [0.3, 0.5, 0.4],
     "params": {"roughness": 0.8}},
    {"mesh": "sphere", "material": "glass", "position": [-0.5, -0.6, 1.5], "radius": 0.35},
    {"mesh": "sphere", "material": "glass", "position": [0.5, -0.6, 0.5], "radius": 0.35}
  ]})";

std::string packages() {
  return test::writePackagesFromTexts("instancing",
                                      {"material plastic { shading lit\n param roughness: float = 0.3 in [0, 1]\n"
                                       " surface { baseColor = vec3(0.8, 0.3, 0.1)\n roughness = params.roughness } }",
                                       "material glass { shading lit\n blending transparent\n"
                                       " surface { baseColor = vec3(0.2, 0.5, 0.9)\n alpha = 0.5 } }"});
}

FrameDesc oneDrawPerObject(const FrameDesc& frame) {
  FrameDesc split = frame;
  split.draws = oneDrawPerInstance(frame.draws);
  return split;
}

void expectSameImage(const FrameResult& a, const FrameResult& b) {
  ASSERT_EQ(a.hdr.size(), b.hdr.size());
  double worst = 0;
  for (size_t i = 0; i < a.hdr.size(); ++i) worst = std::max(worst, double(std::abs(a.hdr[i] - b.hdr[i])));
  // The same shader on the same vertices: only the draw boundaries differ, so the pixels agree
  // exactly (one binary16 step of slack for a rasteriser's order of operations).
  EXPECT_LE(worst, 1e-3);
  EXPECT_EQ(a.ldr, b.ldr);
}

void checkSceneOn(RenderBackend& backend) {
  std::string error;
  auto scene = parseScene("instancing.json", kScene, &error);
  ASSERT_TRUE(scene) << error;
  auto prepared = SceneFrame::prepare(*scene, packages(), &error);
  ASSERT_NE(prepared, nullptr) << error;
  const FrameDesc& frame = prepared->frame();
  // Five opaque objects in two parameter sets and two meshes: three draws (sphere ×2 at
  // roughness 0.3 with the box apart, sphere ×2 at 0.8); the transparent ones one each.
  ASSERT_EQ(frame.draws.size(), 5u);
  EXPECT_EQ(frame.draws[0].instances.size(), 2u);
  EXPECT_EQ(frame.draws[1].instances.size(), 1u);
  EXPECT_EQ(frame.draws[2].instances.size(), 2u);
  for (size_t i = 3; i < 5; ++i) {
    EXPECT_EQ(frame.draws[i].blending, Blending::Transparent);
    EXPECT_EQ(frame.draws[i].instances.size(), 1u);
  }
  // Far to near: the sphere at z = 0.5 before the one at z = 1.5.
  EXPECT_LT(frame.draws[3].instances[0].rows[2][3], frame.draws[4].instances[0].rows[2][3]);

  FrameResult instanced, separate;
  ASSERT_TRUE(backend.render(frame, &instanced, &error)) << error;
  ASSERT_TRUE(backend.render(oneDrawPerObject(frame), &separate, &error)) << error;
  expectSameImage(instanced, separate);
  EXPECT_TRUE(backend.validationErrors().empty())
      << (backend.validationErrors().empty() ? "" : backend.validationErrors().front());
}

TEST(Instancing, SceneDrawnInstancedMatchesOneDrawPerObjectOnVulkan) {
  std::string error;
  auto backend = createVulkanBackend({true}, &error);
  ASSERT_NE(backend, nullptr) << error;
  checkSceneOn(*backend);
}

TEST(Instancing, SceneDrawnInstancedMatchesOneDrawPerObjectOnGl) {
  std::string error;
  auto backend = createGlBackend(&error);
  ASSERT_NE(backend, nullptr) << error;
  checkSceneOn(*backend);
}

// The app-embedding API: MaterialInstance::draw with N transforms.
std::shared_ptr<Material> flatColour() {
  const std::string dir = test::writePackagesFromTexts(
      "instancing-app", {"material flat { shading unlit\n surface { baseColor = vec3(0.8, 0.4, 0.2) } }"});
  std::string error;
  auto loaded = LoadedMaterial::load(dir + "/flat.matpkg", &error);
  EXPECT_TRUE(loaded) << error;
  if (!loaded) return nullptr;
  auto material = Material::create(std::move(*loaded), {"high", false, 0}, &error);
  EXPECT_NE(material, nullptr) << error;
  return material;
}

Mesh square() {  // [-1, -0.5]² in clip space
  Mesh mesh;
  for (const auto& p : {std::array<float, 2>{-1, -1}, {-0.5f, -1}, {-0.5f, -0.5f}, {-1, -0.5f}})
    appendVertex(mesh, Vertex{{p[0], p[1], 0}});
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

std::array<float, 16> placed(float x, float y, float scale) {
  return {scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, 1, 0, x, y, 0, 1};
}

FrameDesc emptyFrame() {
  FrameDesc frame;
  frame.width = 32;
  frame.height = 32;
  for (int i = 0; i < 16; ++i) frame.frame.viewProjection[i] = i % 5 == 0 ? 1.0f : 0.0f;
  return frame;
}

void checkAppDrawOn(RenderBackend& backend) {
  auto material = flatColour();
  ASSERT_NE(material, nullptr);
  auto instance = material->createInstance();
  const Mesh mesh = square();
  const std::vector<std::array<float, 16>> models = {placed(0, 0, 1), placed(1, 0.5f, 1), placed(1.25f, 1.25f, 0.5f)};
  FrameDesc instanced = emptyFrame(), separate = emptyFrame();
  instanced.draws.push_back(instance->draw(mesh, models));
  for (const auto& m : models) separate.draws.push_back(instance->draw(mesh, m));
  std::string error;
  FrameResult a, b;
  ASSERT_TRUE(backend.render(instanced, &a, &error)) << error;
  ASSERT_TRUE(backend.render(separate, &b, &error)) << error;
  expectSameImage(a, b);
  // Each square is drawn: its centre pixel is lit, the background is not.
  auto lit = [&](float x, float y) {
    const auto col = size_t((x + 1) * 16), row = size_t((1 - y) * 16);  // HDR rows top to bottom
    return a.hdr[(row * 32 + col) * 4] > 0.1f;
  };
  EXPECT_TRUE(lit(-0.75f, -0.75f));
  EXPECT_TRUE(lit(0.25f, -0.25f));
  EXPECT_TRUE(lit(0.87f, 0.87f));
  EXPECT_FALSE(lit(0.5f, -0.75f));
  EXPECT_TRUE(backend.validationErrors().empty())
      << (backend.validationErrors().empty() ? "" : backend.validationErrors().front());
}

TEST(Instancing, AppDrawWithTransformsMatchesOneDrawEachOnVulkan) {
  std::string error;
  auto backend = createVulkanBackend({true}, &error);
  ASSERT_NE(backend, nullptr) << error;
  checkAppDrawOn(*backend);
}

TEST(Instancing, AppDrawWithTransformsMatchesOneDrawEachOnGl) {
  std::string error;
  auto backend = createGlBackend(&error);
  ASSERT_NE(backend, nullptr) << error;
  checkAppDrawOn(*backend);
}

// Instance counts out of bounds: refused with the draw and the bound named, nothing drawn.
void checkBoundsOn(RenderBackend& backend) {
  auto material = flatColour();
  ASSERT_NE(material, nullptr);
  auto instance = material->createInstance();
  const Mesh mesh = square();
  std::string error;
  FrameResult result;

  FrameDesc none = emptyFrame();
  none.draws.push_back(instance->draw(mesh, placed(0, 0, 1)));
  none.draws.push_back(none.draws.back());
  none.draws.back().instances.clear();
  EXPECT_FALSE(backend.render(none, &result, &error));
  EXPECT_NE(error.find("draw 1: has no instances"), std::string::npos) << error;

  FrameDesc tooMany = emptyFrame();
  tooMany.draws.push_back(instance->draw(mesh, placed(0, 0, 1)));
  tooMany.draws.back().instances.assign(abi::kMaxInstancesPerDraw + 1, abi::InstanceTransform{});
  EXPECT_FALSE(backend.render(tooMany, &result, &error));
  EXPECT_NE(error.find("draw 0: 65537 instances, more than the 65536 a draw may have"), std::string::npos) << error;

  // Four full draws are the frame's bound; a fifth instance takes it past. Zero transforms: no
  // pixels, so the frame at the bound is cheap to draw.
  FrameDesc frameFull = emptyFrame();
  for (int i = 0; i < 5; ++i) {
    frameFull.draws.push_back(instance->draw(mesh, placed(0, 0, 1)));
    frameFull.draws.back().instances.assign(i < 4 ? abi::kMaxInstancesPerDraw : 1, abi::InstanceTransform{});
  }
  EXPECT_FALSE(backend.render(frameFull, &result, &error));
  EXPECT_NE(error.find("draw 4: takes the frame to 262145 instances, more than the 262144"), std::string::npos)
      << error;
  frameFull.draws.pop_back();  // exactly at the bound: drawn
  EXPECT_TRUE(backend.render(frameFull, &result, &error)) << error;
  EXPECT_TRUE(backend.validationErrors().empty())
      << (backend.validationErrors().empty() ? "" : backend.validationErrors().front());
}

TEST(Instancing, InstanceCountsPastTheBoundsAreErrorsOnVulkan) {
  std::string error;
  auto backend = createVulkanBackend({true}, &error);
  ASSERT_NE(backend, nullptr) << error;
  checkBoundsOn(*backend);
}

TEST(Instancing, InstanceCountsPastTheBoundsAreErrorsOnGl) {
  std::string error;
  auto backend = createGlBackend(&error);
  ASSERT_NE(backend, nullptr) << error;
  checkBoundsOn(*backend);
}

// A normal map tilts the shading normal by the same angle whatever the object's scale: the
// tangent, scaled with the object like the position, is normalized as the normal is (a floor
// scaled 4 once tilted its map 4× as steeply). The same lit, mapped plane at scale 1 and at scale
// 4 seen from 4× as far (a directional sun, an environment at infinity) is the same image.
void checkMapTiltIndependentOfScaleOn(RenderBackend& backend) {
  const std::string packages = test::writePackagesFromTexts(
      "instancing_normal_map", {"material tilted { shading lit\n surface { baseColor = vec3(0.5, 0.5, 0.5)\n"
                                " roughness = 0.3\n normal = vec3(0.35, -0.25, 1.0) } }"});
  const auto render = [&](double scale, FrameResult* out) {
    const std::string s = std::to_string(scale);
    const std::string text = R"({"width": 64, "height": 48, "tier": "high", "camera": {"position": [0, )" +
                             std::to_string(1.5 * scale) + ", " + std::to_string(1.2 * scale) +
                             R"(], "target": [0, 0, 0], "fovY": 45},
      "sun": {"direction": [0.3, -0.6, -0.74], "illuminance": 110000}, "sky": {"luminance": 6000},
      "objects": [{"mesh": "plane", "material": "tilted", "scale": [)" +
                             s + ", " + s + ", " + s + "]}]}";
    std::string error;
    auto scene = parseScene("scaled_plane.json", text, &error);
    ASSERT_TRUE(scene) << error;
    auto prepared = SceneFrame::prepare(*scene, packages, &error);
    ASSERT_NE(prepared, nullptr) << error;
    ASSERT_TRUE(backend.render(prepared->frame(), out, &error)) << error;
  };
  FrameResult unit, scaled;
  render(1.0, &unit);
  render(4.0, &scaled);
  ASSERT_EQ(unit.ldr.size(), scaled.ldr.size());
  int worst = 0;
  for (size_t i = 0; i < unit.ldr.size(); ++i) worst = std::max(worst, std::abs(int(unit.ldr[i]) - int(scaled.ldr[i])));
  // Only rounding differs (positions 4× as large, the same angles): one 8-bit step of slack.
  EXPECT_LE(worst, 1);
  EXPECT_TRUE(backend.validationErrors().empty())
      << (backend.validationErrors().empty() ? "" : backend.validationErrors().front());
}

TEST(Instancing, NormalMapTiltDoesNotDependOnTheObjectsScaleOnVulkan) {
  std::string error;
  auto backend = createVulkanBackend({true}, &error);
  ASSERT_NE(backend, nullptr) << error;
  checkMapTiltIndependentOfScaleOn(*backend);
}

TEST(Instancing, NormalMapTiltDoesNotDependOnTheObjectsScaleOnGl) {
  std::string error;
  auto backend = createGlBackend(&error);
  ASSERT_NE(backend, nullptr) << error;
  checkMapTiltIndependentOfScaleOn(*backend);
}

}  // namespace
}  // namespace facet::runtime
