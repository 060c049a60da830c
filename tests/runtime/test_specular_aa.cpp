// Specular anti-aliasing on the hammered floor (examples/materials/hammered_floor.mat, the floor
// tinted black, so the image is all specular), measured with 1 sample per pixel against 16 samples
// per pixel without it (tools/specular_aa_figures.h). What is asserted: the filter leaves a
// surface whose normal does not vary exactly as it was (the kernel is 0 there: no bias on flat
// floors), and on the floor it is for (tests/data/scenes/hammered_floor_sky.json: an outdoor sky's
// environment and a sun whose glints stay below the tone curve's white) the floor aliases without
// it and the example's variance (0.02, the language's default) brings it closer to the reference,
// keeps its light and flickers less. docs/material-models.md reports the figures, and those of the floor where it
// loses.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <string>

#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "specular_aa_figures.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using namespace facet::runtime;
using namespace facet::supersample;

// The example material, and the same material without its specularAntiAliasing line.
std::string floorText(bool filtered) {
  std::string text = facet::test::readText(facet::test::examplePath("materials/hammered_floor.mat"));
  if (filtered) return text;
  const size_t at = text.find("    specularAntiAliasing");
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) text.erase(at, text.find('\n', at) - at + 1);
  return text;
}

struct Fixture {
  std::optional<Scene> scene;
  std::string plain, filtered;
};

Fixture load(const std::string& scene, std::string* error) {
  Fixture f;
  SceneReadOptions read;
  read.assetRoot = facet::test::sourceDir();  // the scene reads the example's normal map
  f.scene = loadScene(facet::test::sourceDir() + "/tests/data/scenes/" + scene, error, read);
  f.plain = facet::test::writePackagesFromTexts("specular_aa_plain", {floorText(false)});
  f.filtered = facet::test::writePackagesFromTexts("specular_aa_filtered", {floorText(true)});
  return f;
}

TEST(SpecularAntiAliasing, LeavesAFlatFloorExactlyAsItWasOnVulkan) {
  std::string error;
  Fixture f = load("hammered_floor_aa.json", &error);
  ASSERT_TRUE(f.scene) << error;
  f.scene->objects[0].textures.erase("ripples");  // the default texture: a flat normal
  auto backend = createVulkanBackend(VulkanOptions{}, &error);
  ASSERT_TRUE(backend) << error;
  FrameResult plain, filtered;
  ASSERT_TRUE(render(*backend, *f.scene, 1, 0, f.plain, &plain, &error)) << error;
  ASSERT_TRUE(render(*backend, *f.scene, 1, 0, f.filtered, &filtered, &error)) << error;
  EXPECT_GT(hdrSum(plain), 0.0);
  EXPECT_EQ(plain.hdr, filtered.hdr);
  for (const std::string& e : backend->validationErrors()) ADD_FAILURE() << "validation: " << e;
}

TEST(SpecularAntiAliasing, IsMeasuredAgainstSixteenSamplesOnVulkan) {
  std::string error;
  Fixture f = load("hammered_floor_sky.json", &error);
  ASSERT_TRUE(f.scene) << error;
  auto backend = createVulkanBackend(VulkanOptions{}, &error);
  ASSERT_TRUE(backend) << error;
  Reference reference;
  ASSERT_TRUE(measureReference(*backend, *f.scene, f.plain, &reference, &error)) << error;
  SpecularAaFigures without, with;
  ASSERT_TRUE(measureOneSample(*backend, *f.scene, f.plain, reference, &without, &error)) << error;
  ASSERT_TRUE(measureOneSample(*backend, *f.scene, f.filtered, reference, &with, &error)) << error;
  std::printf(
      "summed specular / reference: %.4f without, %.4f with; PSNR %.2f, %.2f dB (of HDR %.2f, %.2f); flicker "
      "%.4f, %.4f (beyond the reference's %.4f, %.4f)\n",
      without.specularRatio, with.specularRatio, without.psnr, with.psnr, without.psnrHdr, with.psnrHdr,
      without.flicker, with.flicker, without.flickerBeyondReference, with.flickerBeyondReference);
  // The floor aliases at 1 sample per pixel (measured 29.95 dB, 0.431 steps of flicker beyond the
  // reference's 0.283) and keeps the reference's light (1.0015).
  EXPECT_LT(without.psnr, 35.0);
  EXPECT_GT(without.flickerBeyondReference, 0.3);
  EXPECT_NEAR(without.specularRatio, 1.0, 0.02);
  // The example's variance 0.02, held to the goals it ships for: measured 0.9932 of the light,
  // +0.98 dB and 0.4234 steps of flicker beyond the reference's (0.0079 fewer). The kernel doubled
  // (variance 0.04, a pixel's box footprint) keeps 0.9783 of the light and zeroed gains nothing:
  // the bounds below hold neither.
  EXPECT_NEAR(with.specularRatio, 1.0, 0.02);
  EXPECT_GT(with.psnr, without.psnr + 0.8);
  EXPECT_LT(with.flickerBeyondReference, without.flickerBeyondReference - 0.005);
  for (const std::string& e : backend->validationErrors()) ADD_FAILURE() << "validation: " << e;
}

}  // namespace
