#include "shadow_frames.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "facet/runtime/png.h"
#include "facet/runtime/scene_frame.h"
#include "facet/runtime/vulkan_backend.h"
#include "facet/scene/scene.h"
#include "facet/shadow_reference/camera_rays.h"
#include "facet/shadow_reference/rendered_visibility.h"
#include "facet/shadow_reference/sun_visibility.h"
#include "test_compile.h"
#include "test_support.h"

namespace facet::runtime::shadow_frames {

using shadow_reference::PixelKind;

const std::string& packages() {
  static const std::string dir = [] {
    compiler::BuildOptions options;
    options.shadowCascadeCounts = {0, 1, 2, 4};
    options.vertexSlopeBias = true;  // both slope stages (docs/shadows.md, "Bias")
    return test::writePackagesFromTexts(
        "vulkan-shadows", {"material plastic { shading lit\n surface { baseColor = vec3(0.7, 0.7, 0.7) } }"}, options);
  }();
  return dir;
}

const std::string& spotPackages() {
  static const std::string dir = [] {
    compiler::BuildOptions options;
    options.pointLightCounts = {1};
    options.spotShadows = true;
    options.vertexSlopeBias = true;
    return test::writePackagesFromTexts(
        "vulkan-spot-shadows", {"material plastic { shading lit\n surface { baseColor = vec3(0.7, 0.7, 0.7) } }"},
        options);
  }();
  return dir;
}

std::string withCasting(const std::string& json, int light, bool casts) {
  if (light == kSun) return withSunCasting(json, casts);
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(json);
  scene["lights"][size_t(light)]["castShadows"] = casts;
  return scene.dump();
}

std::string withSunCasting(const std::string& json, bool casts) {
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(json);
  scene["sun"]["castShadows"] = casts;
  return scene.dump();
}

std::string sunOnlyScene(const std::string& fileName) {
  nlohmann::ordered_json scene =
      nlohmann::ordered_json::parse(test::readText(test::sourceDir() + "/tests/data/scenes/shadows/" + fileName));
  scene["sky"]["luminance"] = 0;
  for (auto& object : scene["objects"]) {
    object["material"] = "plastic";
    object.erase("params");
  }
  return scene.dump();
}

const char* apiName(Api api) { return api == Api::Vulkan ? "vulkan" : "gl"; }

std::unique_ptr<RenderBackend> makeBackend(Api api) {
  std::string error;
  std::unique_ptr<RenderBackend> backend =
      api == Api::Vulkan ? createVulkanBackend({true}, &error) : createGlBackend(GlOptions{}, &error);
  EXPECT_TRUE(backend) << error;
  return backend;
}

FrameResult render(RenderBackend& backend, const std::string& json, const std::string& name,
                   abi::ShadowUniforms* shadow) {
  FrameResult result;
  std::string error;
  auto scene = parseScene(name + ".json", json, &error);
  EXPECT_TRUE(scene) << error;
  if (!scene) return result;
  auto frame = SceneFrame::prepare(*scene, scene->lights.empty() ? packages() : spotPackages(), &error);
  EXPECT_TRUE(frame) << error;
  if (!frame) return result;
  if (shadow) *shadow = frame->frame().shadow ? frame->frame().shadow->uniforms : abi::ShadowUniforms{};
  EXPECT_TRUE(backend.render(frame->frame(), &result, &error)) << error;
  EXPECT_TRUE(backend.validationErrors().empty()) << backend.validationErrors().front();
  return result;
}

namespace {

std::optional<shadow_reference::SunVisibility> visibilityOf(const shadow_reference::ShadowScene& scene, int light,
                                                            std::string* error) {
  return light == kSun ? shadow_reference::SunVisibility::build(scene, error)
                       : shadow_reference::SunVisibility::buildSpot(scene, size_t(light), error);
}

}  // namespace

shadow_reference::ReferenceImage referenceOf(const std::string& json, const std::string& name, double footprint,
                                             int light) {
  std::string error;
  auto scene = shadow_reference::parseShadowScene(name + ".json", json, &error);
  EXPECT_TRUE(scene) << error;
  if (!scene) return {};
  auto sun = visibilityOf(*scene, light, &error);
  EXPECT_TRUE(sun) << error;
  if (!sun) return {};
  shadow_reference::ReferenceOptions options;
  options.footprintRadius = footprint;
  options.footprintSamples = 16;
  return renderReference(*scene, *sun, options);
}

std::string renderToPng(RenderBackend& backend, const std::string& json, const std::string& name,
                        abi::ShadowUniforms* shadow) {
  const FrameResult result = render(backend, json, name, shadow);
  if (result.ldr.empty()) return "";
  std::string error;
  std::vector<uint8_t> png;
  EXPECT_TRUE(encodePng(result.width, result.height, result.ldr, &png, &error)) << error;
  static const std::string frames = test::scratchDir("vulkan-shadows-frames");
  const std::string path = frames + "/" + name + ".png";
  FILE* file = std::fopen(path.c_str(), "wb");
  EXPECT_NE(file, nullptr) << path;
  if (!file) return "";
  std::fwrite(png.data(), 1, png.size(), file);
  std::fclose(file);
  return path;
}

Measured measure(const std::string& json, const std::string& name, double footprint, Api api, int light) {
  auto backend = makeBackend(api);
  if (!backend) return {};
  return measure(*backend, api, json, name, footprint, light);
}

Measured measure(RenderBackend& backend, Api api, const std::string& json, const std::string& name, double footprint,
                 int light) {
  Measured out;
  std::string error;
  const std::string prefix = std::string(apiName(api)) + "-" + name;
  const std::string shadowed = renderToPng(backend, withCasting(json, light, true), prefix + "-shadowed", &out.shadow);
  const std::string unshadowed = renderToPng(backend, withCasting(json, light, false), prefix + "-unshadowed");
  auto rendered = shadow_reference::visibilityFromFrames(shadowed, unshadowed, &error);
  EXPECT_TRUE(rendered) << error;
  auto scene = shadow_reference::parseShadowScene(name + ".json", json, &error);
  EXPECT_TRUE(scene) << error;
  if (!rendered || !scene) return out;
  auto sun = visibilityOf(*scene, light, &error);
  EXPECT_TRUE(sun) << error;
  if (!sun) return out;
  shadow_reference::ReferenceOptions options;
  options.footprintRadius = footprint;
  options.footprintSamples = 16;
  out.reference = renderReference(*scene, *sun, options);
  out.rendered = *rendered;
  auto score = shadow_reference::scoreShadows(out.reference, out.rendered, &error);
  EXPECT_TRUE(score) << error;
  if (score) out.score = *score;
  const shadow_reference::CameraRays camera(scene->scene);
  out.cameraPosition = glm::dvec3(scene->scene.camera.position);
  out.viewProjection = viewProjection(scene->scene);
  out.points.assign(out.reference.pixels.size(), glm::dvec3(std::numeric_limits<double>::quiet_NaN()));
  for (uint32_t y = 0; y < out.reference.height; ++y)
    for (uint32_t x = 0; x < out.reference.width; ++x) {
      const shadow_reference::Ray ray = camera.ray(x, y);
      if (const auto hit = sun->bvh().closestHit(ray))
        out.points[size_t(y) * out.reference.width + x] = ray.origin + hit->t * ray.direction;
    }
  return out;
}

double meanVisibility(const Measured& m, float visible, size_t* count) {
  double sum = 0;
  *count = 0;
  for (size_t i = 0; i < m.reference.pixels.size(); ++i) {
    const auto& pixel = m.reference.pixels[i];
    if (pixel.kind != PixelKind::Surface || pixel.footprint != visible || std::isnan(m.rendered.values[i])) continue;
    sum += m.rendered.values[i];
    ++*count;
  }
  return *count ? sum / double(*count) : std::nan("");
}

double viewDepth(const Measured& m, const glm::dvec3& p) {
  const glm::dvec3 forward(m.shadow.cameraForward[0], m.shadow.cameraForward[1], m.shadow.cameraForward[2]);
  return glm::dot(p - m.cameraPosition, forward);
}

int cascadeAt(const Measured& m, const glm::dvec3& p) {
  const double d = viewDepth(m, p);
  int cascade = 0;
  for (int i = 0; i < 3; ++i) cascade += d >= m.shadow.splits[i] ? 1 : 0;
  return cascade;
}

double texelSizeAt(const Measured& m, const glm::dvec3& p) {
  // cascadeScale.x is atlas u per metre of the sun's frame; one texel is 1 / atlasSize of u.
  return double(m.shadow.fadeAtlas[3]) / double(m.shadow.cascadeScale[cascadeAt(m, p)][0]);
}

shadow_reference::ShadowScore scoreWhere(const Measured& m, const std::function<bool(size_t)>& keep) {
  shadow_reference::ReferenceImage kept = m.reference;
  for (size_t i = 0; i < kept.pixels.size(); ++i)
    if (!keep(i)) kept.pixels[i].kind = PixelKind::Sky;
  std::string error;
  const auto score = shadow_reference::scoreShadows(kept, m.rendered, &error);
  EXPECT_TRUE(score) << error;
  return score ? *score : shadow_reference::ShadowScore{};
}

}  // namespace facet::runtime::shadow_frames
