// The tiers keep the promises the brief makes about their maths, and every tier renders.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>

#include "facet/compiler/spirv_cost.h"
#include "facet/compiler/spirv_tools_backend.h"
#include "facet/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "test_support.h"

namespace {

using facet::package::Stage;

std::vector<uint32_t> spirvOf(const facet::compiler::BuildResult& built, const std::string& key, Stage stage) {
  for (const auto& v : built.package.variants) {
    if (v.key != key) continue;
    for (const auto& s : v.shaders) {
      if (s.stage != stage || s.target != facet::package::Target::Spirv) continue;
      std::vector<uint32_t> words(s.code.size() / 4);
      std::memcpy(words.data(), s.code.data(), s.code.size());
      return words;
    }
  }
  ADD_FAILURE() << "no " << key << " SPIR-V";
  return {};
}

facet::compiler::StageCost costOf(const std::vector<uint32_t>& words) {
  facet::compiler::StageCost cost;
  std::string error;
  EXPECT_TRUE(facet::compiler::analyseSpirvCost(words, &cost, &error)) << error;
  return cost;
}

using facet::test::psnr;

}  // namespace

TEST(Tiers, ZiomaSpecularHasOneDivision) {
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"));
  ASSERT_TRUE(built);
  // The whole mid fragment stage: Zioma's fused term is its only division (per-vertex diffuse
  // and the precision clamps add none). The GGX/Smith tiers divide twice (D and V).
  EXPECT_EQ(costOf(spirvOf(*built, "mid.dir1", Stage::Fragment)).divisions, 1u);
  EXPECT_EQ(costOf(spirvOf(*built, "high.dir1", Stage::Fragment)).divisions, 2u);
  EXPECT_LT(costOf(spirvOf(*built, "mid.dir1", Stage::Fragment)).aluOps,
            costOf(spirvOf(*built, "high.dir1", Stage::Fragment)).aluOps);
}

TEST(Tiers, VertexDiffuseLeavesNoDiffuseLightingInTheFragmentStage) {
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"));
  ASSERT_TRUE(built);
  // Lambert's 1/π (0.318309873 as a float constant) is where diffuse lighting is evaluated.
  auto usesInvPi = [](const std::vector<uint32_t>& words) {
    return facet::compiler::disassembleSpirv(words).find("0.318309873") != std::string::npos;
  };
  EXPECT_TRUE(usesInvPi(spirvOf(*built, "high.dir1", Stage::Fragment)));
  EXPECT_FALSE(usesInvPi(spirvOf(*built, "high.dir1", Stage::Vertex)));
  EXPECT_FALSE(usesInvPi(spirvOf(*built, "mid.dir1", Stage::Fragment)));
  EXPECT_TRUE(usesInvPi(spirvOf(*built, "mid.dir1", Stage::Vertex)));
}

TEST(Tiers, ReferenceIsHighpAndMobileTiersAreMostlyMediump) {
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"));
  ASSERT_TRUE(built);
  EXPECT_EQ(costOf(spirvOf(*built, "reference.dir1", Stage::Fragment)).relaxedOps, 0u);
  EXPECT_GT(costOf(spirvOf(*built, "high.dir1", Stage::Fragment)).relaxedPercent(), 85.0);
  EXPECT_GT(costOf(spirvOf(*built, "mid.dir1", Stage::Fragment)).relaxedPercent(), 85.0);
}

// Every supported tier of the example scene renders on both backends with no validation error,
// the backends agree, and each tier's image is measured against `reference` (8-bit PSNR).
// The bound is a floor that catches a broken tier, not a quality target; the figures are
// printed for the record.
TEST(Tiers, EveryTierRendersOnBothBackendsAndIsMeasuredAgainstReference) {
  std::string packages = facet::test::writeExamplePackages("tier-packages");
  std::string error;
  auto scene = facet::runtime::loadScene(facet::test::examplePath("scenes/spheres.json"), &error);
  ASSERT_TRUE(scene) << error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  ASSERT_TRUE(vk) << error;
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(gl) << error;

  std::map<std::string, facet::runtime::FrameResult> images;
  for (const char* tier : {"reference", "high", "mid"}) {
    SCOPED_TRACE(tier);
    scene->tier = tier;
    auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
    ASSERT_TRUE(frame) << error;
    facet::runtime::FrameResult a, b;
    ASSERT_TRUE(vk->render(frame->frame(), &a, &error)) << error;
    ASSERT_TRUE(gl->render(frame->frame(), &b, &error)) << error;
    int maxDiff = 0;
    for (size_t i = 0; i < a.ldr.size(); ++i) maxDiff = std::max(maxDiff, std::abs(int(a.ldr[i]) - int(b.ldr[i])));
    EXPECT_LE(maxDiff, 1) << "Vulkan and GL differ";
    images[tier] = std::move(a);
  }
  EXPECT_TRUE(vk->validationErrors().empty());
  EXPECT_TRUE(gl->validationErrors().empty());
  for (const char* tier : {"high", "mid"}) {
    double db = psnr(images[tier].ldr, images["reference"].ldr);
    std::printf("tier %-5s vs reference: %.1f dB (8-bit PSNR, spheres.json)\n", tier, db);
    EXPECT_GT(db, 30.0) << tier;
  }
}

TEST(Tiers, MetalGetsHalfWhereGlesGetsMediump) {
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"));
  ASSERT_TRUE(built);
  auto msl = [&](const std::string& key) {
    for (const auto& v : built->package.variants)
      if (v.key == key)
        for (const auto& s : v.shaders)
          if (s.stage == Stage::Fragment && s.target == facet::package::Target::Msl) return std::string(s.code.begin(), s.code.end());
    return std::string();
  };
  EXPECT_NE(msl("high.dir1").find("half "), std::string::npos);
  EXPECT_NE(msl("mid.dir1").find("half "), std::string::npos);
  EXPECT_EQ(msl("reference.dir1").find("half"), std::string::npos);
}

TEST(Tiers, MaterialOverrideReplacesOneChoiceOfOneTier) {
  auto preset = facet::test::buildText("material m { param r: float = 0.4\n surface { roughness = params.r } }");
  auto fastv = facet::test::buildText(
      "material m { param r: float = 0.4\n surface { roughness = params.r }\n tier high { specular = ggx_fastv } }");
  ASSERT_TRUE(preset && fastv);
  // Hammon's V has no square roots: the overridden high tier loses the two of height-correlated
  // Smith; the mid tier, not overridden, is unchanged.
  auto transcendentals = [](const facet::compiler::BuildResult& b, const std::string& key) {
    return costOf(spirvOf(b, key, Stage::Fragment)).transcendentalOps;
  };
  EXPECT_EQ(transcendentals(*fastv, "high.dir1") + 2, transcendentals(*preset, "high.dir1"));
  EXPECT_EQ(transcendentals(*fastv, "mid.dir1"), transcendentals(*preset, "mid.dir1"));
  EXPECT_EQ(spirvOf(*fastv, "reference.dir1", Stage::Fragment), spirvOf(*preset, "reference.dir1", Stage::Fragment));
}
