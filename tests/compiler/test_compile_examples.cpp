// Every example material compiles, and every target in its package is valid code.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "facet/compiler/glslang_backend.h"
#include "facet/compiler/spirv_tools_backend.h"
#include "facet/package/package.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using facet::package::Stage;
using facet::package::Target;

std::string text(const facet::package::Shader& s) { return {s.code.begin(), s.code.end()}; }

const facet::package::Shader* find(const facet::package::Variant& v, Stage stage, Target target) {
  for (const auto& s : v.shaders)
    if (s.stage == stage && s.target == target) return &s;
  return nullptr;
}

}  // namespace

TEST(Examples, AtLeastThreeMaterialsShip) { EXPECT_GE(facet::test::exampleMaterials().size(), 3u); }

TEST(Examples, EveryMaterialCompilesToValidShadersForAllTargets) {
  for (const std::string& path : facet::test::exampleMaterials()) {
    SCOPED_TRACE(path);
    auto built = facet::test::buildFile(path);
    ASSERT_TRUE(built);
    // Through the package format and back, as an app would get them.
    auto read = facet::package::read(facet::package::write(built->package));
    ASSERT_TRUE(read.package) << read.error;
    ASSERT_FALSE(read.package->variants.empty());
    // Every supported tier is built by default, the low tier's table with it where a light reads it.
    for (const char* key : {"reference.dir1", "high.dir1", "mid.dir1", "low.dir0", "low.dir1"}) {
      bool found = false;
      for (const auto& variant : read.package->variants) found = found || variant.key == key;
      EXPECT_TRUE(found) << key;
    }
    // (A cloth material's lights read no `lut` lobe: its package ships no table.)
    const auto* fragment = find(read.package->variants.front(), Stage::Fragment, Target::GlslEs300);
    ASSERT_TRUE(fragment);
    const bool cloth = facet::test::readText(path).find("shading cloth") != std::string::npos;
    ASSERT_EQ(read.package->textures.size(), cloth ? 0u : 1u);
    if (!cloth) {
      EXPECT_EQ(read.package->textures[0].texels, built->package.textures[0].texels);
    }
    for (const auto& variant : read.package->variants) {
      SCOPED_TRACE(variant.key);
      for (Stage stage : {Stage::Vertex, Stage::Fragment}) {
        const auto* spirv = find(variant, stage, Target::Spirv);
        ASSERT_TRUE(spirv);
        ASSERT_EQ(spirv->code.size() % 4, 0u);
        std::vector<uint32_t> words(spirv->code.size() / 4);
        std::memcpy(words.data(), spirv->code.data(), spirv->code.size());
        std::string log;
        EXPECT_TRUE(facet::compiler::validateSpirv(words, &log)) << log;

        const auto* msl = find(variant, stage, Target::Msl);
        ASSERT_TRUE(msl);
        std::string metal = text(*msl);
        EXPECT_NE(metal.find("#include <metal_stdlib>"), std::string::npos);
        EXPECT_NE(metal.find(stage == Stage::Vertex ? "vertex main0_out main0(" : "fragment main0_out main0("),
                  std::string::npos)
            << metal;
      }
      // GLSL ES 3.00: both stages parsed and linked together by glslang, as an ES driver would.
      const auto* vs = find(variant, Stage::Vertex, Target::GlslEs300);
      const auto* fs = find(variant, Stage::Fragment, Target::GlslEs300);
      ASSERT_TRUE(vs && fs);
      EXPECT_EQ(text(*vs).rfind("#version 300 es\n", 0), 0u);
      std::string log;
      EXPECT_TRUE(facet::compiler::checkGlslEs300({text(*vs), text(*fs)}, &log)) << log;
    }
  }
}

TEST(Examples, CompilationIsDeterministic) {
  const std::string path = facet::test::exampleMaterials().front();
  auto a = facet::test::buildFile(path);
  auto b = facet::test::buildFile(path);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(facet::package::write(a->package), facet::package::write(b->package));
}

// A texture's sampler uniform lives in the interface's `facet_` namespace, so a parameter named
// like a chunk function (material_f0 in shading_standard.glsl) compiles on every target.
TEST(Examples, TextureNamedLikeAChunkFunctionCompiles) {
  auto built = facet::test::buildText(R"(material tex {
    param f0: texture(srgb) = vec4(1.0)
    surface {
        baseColor = sample(params.f0, vertex.uv0).rgb
    }
}
)");
  ASSERT_TRUE(built);
  EXPECT_FALSE(built->package.variants.empty());
}

TEST(Examples, NoChunkOrTemplateDeclaresANameInTheMaterialSamplerNamespace) {
  for (const char* folder : {"chunks", "templates"})
    for (const auto& entry : std::filesystem::directory_iterator(facet::test::sourceDir() + "/" + folder)) {
      std::string text = facet::test::readText(entry.path().string());
      EXPECT_EQ(text.find("facet_material_"), std::string::npos) << entry.path();
    }
}

// Variants compile on a thread pool; the package may not depend on how many jobs ran.
TEST(Examples, PackageIsByteIdenticalForOneAndTwoJobs) {
  const std::string path = facet::test::examplePath("materials/red_plastic.mat");
  facet::compiler::BuildOptions one, two;
  one.jobs = 1;
  two.jobs = 2;
  one.pointLightCounts = two.pointLightCounts = {0, 1, 2};
  auto a = facet::test::buildFile(path, one);
  auto b = facet::test::buildFile(path, two);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(facet::package::write(a->package), facet::package::write(b->package));
}

// Debug sources (readable GLSL, SPIR-V disassembly) are produced only when asked for.
TEST(Examples, DebugSourcesOnlyWithEmitSources) {
  const std::string path = facet::test::examplePath("materials/red_plastic.mat");
  facet::compiler::BuildOptions quiet, emitting;
  quiet.tiers = emitting.tiers = {facet::permutations::Tier::High};
  emitting.emitSources = true;
  auto a = facet::test::buildFile(path, quiet);
  auto b = facet::test::buildFile(path, emitting);
  ASSERT_TRUE(a && b);
  EXPECT_TRUE(a->sources.empty());
  EXPECT_EQ(b->sources.size(), 10u * b->package.variants.size());
  EXPECT_EQ(facet::package::write(a->package), facet::package::write(b->package));
}
