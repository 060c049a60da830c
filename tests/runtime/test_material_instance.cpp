// Material instances (runtime/material_instance.h): one material, instances with their own
// parameters in persistent GPU uniform blocks, re-uploaded only when a value changed.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "facet/runtime/material_instance.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/render_backend.h"
#include "test_compile.h"

namespace facet::runtime {
namespace {

constexpr uint32_t kWidth = 32, kHeight = 16;

std::shared_ptr<Material> flatColourMaterial() {
  const std::string packages = test::writePackagesFromTexts(
      "material-instance", {"material flat_colour { shading unlit\n param c: color = vec3(0.8, 0.4, 0.2)\n"
                            " param gain: float = 1.0 in [0, 4]\n surface { baseColor = params.c * params.gain } }"});
  std::string error;
  auto loaded = LoadedMaterial::load(packages + "/flat_colour.matpkg", &error);
  EXPECT_TRUE(loaded) << error;
  if (!loaded) return nullptr;
  auto material = Material::create(std::move(*loaded), {"high", true, 0}, &error);
  EXPECT_NE(material, nullptr) << error;
  return material;
}

// A square filling the left half of clip space; translated by +1 in x it fills the right half.
Mesh leftHalf() {
  Mesh mesh;
  for (const auto& p : {std::array<float, 2>{-1, -1}, {0, -1}, {0, 1}, {-1, 1}})
    appendVertex(mesh, Vertex{{p[0], p[1], 0}});
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

std::array<float, 16> translationX(float x) { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, 0, 0, 1}; }

FrameDesc frameOf(const MaterialInstance& left, const MaterialInstance& right, const Mesh& mesh) {
  FrameDesc frame;
  frame.width = kWidth;
  frame.height = kHeight;
  for (int i = 0; i < 16; ++i) frame.frame.viewProjection[i] = i % 5 == 0 ? 1.0f : 0.0f;
  frame.draws.push_back(left.draw(mesh, translationX(0)));
  frame.draws.push_back(right.draw(mesh, translationX(1)));
  return frame;
}

// The HDR pixels of one half (left: columns 0..15).
std::vector<float> half(const FrameResult& result, bool right) {
  std::vector<float> out;
  for (uint32_t row = 0; row < kHeight; ++row)
    for (uint32_t col = right ? kWidth / 2 : 0; col < (right ? kWidth : kWidth / 2); ++col)
      for (int c = 0; c < 4; ++c) out.push_back(result.hdr[(size_t{row} * kWidth + col) * 4 + c]);
  return out;
}

void checkInstancesOn(RenderBackend& backend) {
  auto material = flatColourMaterial();
  ASSERT_NE(material, nullptr);
  const auto colour = material->parameter("c");
  ASSERT_TRUE(colour);
  auto a = material->createInstance();
  auto b = material->createInstance();
  const Mesh mesh = leftHalf();
  const FrameDesc frame = frameOf(*a, *b, mesh);
  std::string error;

  FrameResult same;
  ASSERT_TRUE(backend.render(frame, &same, &error)) << error;
  EXPECT_EQ(half(same, false), half(same, true)) << "two instances with the defaults draw alike";
  EXPECT_EQ(backend.resources().materialBuffers, 2u);
  EXPECT_EQ(backend.resources().materialUploads, 2u);

  // Only b changes: only the right half changes, and only b's block is uploaded.
  ASSERT_TRUE(b->setParameter(*colour, std::array<float, 3>{0.1f, 0.6f, 0.9f}, &error)) << error;
  FrameResult changed;
  ASSERT_TRUE(backend.render(frame, &changed, &error)) << error;
  EXPECT_EQ(half(changed, false), half(same, false));
  EXPECT_NE(half(changed, true), half(same, true));
  EXPECT_EQ(backend.resources().materialUploads, 3u);

  // Nothing changed, or a value set to what it already is: no upload.
  ASSERT_TRUE(b->setParameter(*colour, std::array<float, 3>{0.1f, 0.6f, 0.9f}, &error)) << error;
  FrameResult again;
  ASSERT_TRUE(backend.render(frame, &again, &error)) << error;
  EXPECT_EQ(half(again, true), half(changed, true));
  EXPECT_EQ(backend.resources().materialUploads, 3u);

  // By name, back to the defaults: b draws as a again.
  ASSERT_TRUE(b->setParameter("c", std::array<float, 3>{0.8f, 0.4f, 0.2f}, &error)) << error;
  FrameResult restored;
  ASSERT_TRUE(backend.render(frame, &restored, &error)) << error;
  EXPECT_EQ(half(restored, true), half(restored, false));
  EXPECT_EQ(backend.resources().materialUploads, 4u);
  EXPECT_TRUE(backend.validationErrors().empty())
      << (backend.validationErrors().empty() ? "" : backend.validationErrors().front());
}

TEST(MaterialInstance, ChangingOneInstanceChangesOnlyItsPixelsOnVulkan) {
  std::string error;
  VulkanOptions options;
  options.validation = true;
  auto backend = createVulkanBackend(options, &error);
  ASSERT_NE(backend, nullptr) << error;
  checkInstancesOn(*backend);
}

TEST(MaterialInstance, ChangingOneInstanceChangesOnlyItsPixelsOnGl) {
  std::string error;
  auto backend = createGlBackend(&error);
  ASSERT_NE(backend, nullptr) << error;
  checkInstancesOn(*backend);
}

TEST(MaterialInstance, WrongTypeRangeOrNameIsAnErrorAndLeavesTheValue) {
  auto material = flatColourMaterial();
  ASSERT_NE(material, nullptr);
  auto instance = material->createInstance();
  const UniformBlock before = instance->block();
  std::string error;
  const auto gain = material->parameter("gain");
  ASSERT_TRUE(gain);
  EXPECT_FALSE(instance->setParameter(*gain, std::array<float, 3>{1, 1, 1}, &error));
  EXPECT_NE(error.find("'gain'"), std::string::npos) << error;
  EXPECT_FALSE(instance->setParameter(*gain, 5.0f, &error));
  EXPECT_NE(error.find("outside its range"), std::string::npos) << error;
  EXPECT_FALSE(instance->setParameter("colour", std::array<float, 3>{1, 1, 1}, &error));
  EXPECT_NE(error.find("no parameter 'colour'"), std::string::npos) << error;
  EXPECT_FALSE(instance->setParameter(ParameterHandle{99}, 1.0f, &error));
  EXPECT_FALSE(instance->setTexture(*gain, nullptr, &error));
  EXPECT_NE(error.find("not a texture"), std::string::npos) << error;
  EXPECT_EQ(instance->block().bytes, before.bytes);
  EXPECT_EQ(instance->block().generation, before.generation);
  EXPECT_TRUE(instance->setParameter(*gain, 2.0f, &error)) << error;
  EXPECT_NE(instance->block().generation, before.generation);
}

}  // namespace
}  // namespace facet::runtime
