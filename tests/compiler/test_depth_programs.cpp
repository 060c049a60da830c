// The shadow pass's depth-only programs (docs/shadows.md, "Depth-only programs"): the key
// `<tier>.depth`, built only when shadows are asked for and only for materials that cast;
// position only for opaque materials, the alpha test and just its inputs for masked ones; loaded
// through the runtime's package checks, which hold them to an interface without a colour target.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "facet/compiler/glslang_backend.h"
#include "facet/ir/check.h"
#include "facet/package/package.h"
#include "facet/permutations/variant_key.h"
#include "facet/runtime/material.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

namespace pkg = facet::package;
using facet::permutations::enumerate;
using facet::permutations::Tier;
using facet::permutations::VariantKey;

std::vector<std::string> names(const std::vector<VariantKey>& keys) {
  std::vector<std::string> out;
  for (const VariantKey& k : keys) out.push_back(k.toString());
  return out;
}

const pkg::Variant* variant(const pkg::Package& p, const std::string& key) {
  for (const pkg::Variant& v : p.variants)
    if (v.key == key) return &v;
  return nullptr;
}

std::string code(const pkg::Package& p, const std::string& key, pkg::Stage stage, pkg::Target target) {
  const pkg::Variant* v = variant(p, key);
  EXPECT_TRUE(v) << "no variant " << key;
  if (v)
    for (const pkg::Shader& s : v->shaders)
      if (s.stage == stage && s.target == target) return std::string(s.code.begin(), s.code.end());
  return "";
}

std::string glsl(const pkg::Package& p, const std::string& key, pkg::Stage stage) {
  return code(p, key, stage, pkg::Target::GlslEs300);
}

facet::compiler::BuildOptions withShadows(std::vector<Tier> tiers) {
  facet::compiler::BuildOptions options;
  options.tiers = std::move(tiers);
  options.shadowCascadeCounts = {0, 2};
  return options;
}

// Alpha from the second UV set and a texture; colour, roughness and the normal from everything else.
const char* kLeaf = R"(material leaf {
    shading lit
    blending masked(0.4)
    param albedo: texture(srgb) = vec4(0.3, 0.6, 0.2, 1.0)
    param cut: texture(linear) = vec4(1.0, 1.0, 1.0, 1.0)
    param tint: color = vec3(1.0, 1.0, 1.0)
    param roughness: float = 0.6 in [0, 1]
    surface {
        baseColor = sample(params.albedo, vertex.uv0).rgb * params.tint * vertex.color.rgb
        alpha = sample(params.cut, vertex.uv1 * 2.0).r
        roughness = params.roughness * dot(vertex.normal, vertex.viewDirection)
    }
}
)";

}  // namespace

TEST(DepthPrograms, KeysRoundTripSortAfterTheirTiersVariantsAndMalformedOnesAreRefused) {
  for (const char* text : {"reference.depth", "high.depth", "mid.depth", "low.depth"}) {
    auto key = VariantKey::parse(text);
    ASSERT_TRUE(key) << text;
    EXPECT_TRUE(key->depthOnly);
    EXPECT_EQ(key->toString(), text);
  }
  for (const char* bad : {"depth", "high.depth.pt1", "high.dir1.depth", "high.depth.sh1", "ultra.depth"})
    EXPECT_FALSE(VariantKey::parse(bad)) << bad;
  EXPECT_FALSE(VariantKey::parse("high.dir0")->depthOnly);
  EXPECT_EQ(names(enumerate({true}, {Tier::High, Tier::Low}, nullptr, {0, 1}, {0, 1})),
            (std::vector<std::string>{"high.dir0", "high.dir0.pt1", "high.dir1", "high.dir1.sh1", "high.dir1.pt1",
                                      "high.dir1.sh1.pt1", "high.depth", "low.dir0", "low.dir0.pt1", "low.dir1",
                                      "low.dir1.sh1", "low.dir1.pt1", "low.dir1.sh1.pt1", "low.depth"}));
}

// Today's default output does not grow; transparent and additive materials never get one; an
// unlit opaque material casts (it receives nothing, but it is in the sun's way).
TEST(DepthPrograms, BuiltOnlyWhenShadowsAreAskedForAndOnlyForMaterialsThatCast) {
  EXPECT_EQ(names(enumerate({true}, {Tier::High})), (std::vector<std::string>{"high.dir0", "high.dir1"}));
  EXPECT_EQ(names(enumerate({false, true}, {Tier::Mid}, nullptr, {0}, {0, 4})),
            (std::vector<std::string>{"mid.dir0", "mid.depth"}));
  EXPECT_EQ(names(enumerate({true, false}, {Tier::Mid}, nullptr, {0}, {0, 4})),
            (std::vector<std::string>{"mid.dir0", "mid.dir1", "mid.dir1.sh4"}));
  for (const char* blending : {"opaque", "masked"}) EXPECT_TRUE(facet::permutations::blendingCastsShadows(blending));
  for (const char* blending : {"transparent", "additive"})
    EXPECT_FALSE(facet::permutations::blendingCastsShadows(blending));

  auto glass = facet::test::buildText(
      "material glass { blending transparent\n surface { baseColor = vec3(0.9)\n alpha = 0.3 } }\n", "glass.mat",
      withShadows({Tier::High}));
  ASSERT_TRUE(glass);
  EXPECT_FALSE(variant(glass->package, "high.depth"));
  EXPECT_TRUE(variant(glass->package, "high.dir1.sh2"));
}

// Opaque: the vertex stage reads the position and the instance rows and nothing else, through the
// forward stage's own lines (so the atlas's depths are the receivers' positions); the fragment
// stage is empty. Every tier's program is the same code, which the package stores once.
TEST(DepthPrograms, AnOpaqueMaterialsProgramIsThePositionAlone) {
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"),
                                      withShadows({Tier::High, Tier::Low}));
  ASSERT_TRUE(built);
  const pkg::Package& p = built->package;
  const std::string vertex = glsl(p, "high.depth", pkg::Stage::Vertex);
  for (const char* input : {"in highp vec3 a_position;", "in highp vec4 a_instanceRow0;",
                            "in highp vec4 a_instanceRow2;", "gl_Position=frame.viewProjection*worldPosition;"})
    EXPECT_NE(vertex.find(input), std::string::npos) << input << " in\n" << vertex;
  for (const char* absent : {"a_normal", "a_uv0", " out "}) EXPECT_EQ(vertex.find(absent), std::string::npos) << absent;
  // The forward variant's world position, character for character.
  const std::string transform =
      "highp vec4 worldPosition=vec4(dot(a_instanceRow0,objectPosition),dot(a_instanceRow1,objectPosition),"
      "dot(a_instanceRow2,objectPosition),1.0);";
  EXPECT_NE(vertex.find(transform), std::string::npos) << vertex;
  EXPECT_NE(glsl(p, "high.dir1.sh2", pkg::Stage::Vertex).find(transform), std::string::npos);
  EXPECT_NE(glsl(p, "high.depth", pkg::Stage::Fragment).find("void main(){\n}"), std::string::npos);
  EXPECT_EQ(glsl(p, "high.depth", pkg::Stage::Fragment).find("out "), std::string::npos);
  for (pkg::Stage stage : {pkg::Stage::Vertex, pkg::Stage::Fragment})
    for (pkg::Target target : {pkg::Target::GlslEs300, pkg::Target::Spirv, pkg::Target::Msl})
      EXPECT_EQ(code(p, "high.depth", stage, target), code(p, "low.depth", stage, target));
  // No preshader program: alpha is never preshaded.
  for (const pkg::PreshaderProgram& program : p.preshader.programs)
    for (uint32_t v : program.variants) EXPECT_FALSE(pkg::isDepthProgramKey(p.variants[v].key));
}

// Masked: the alpha test on the surface program reduced to alpha: its UV set and texture, none of
// the colour's, the normal's or the roughness's inputs; at the tier's precision.
TEST(DepthPrograms, AMaskedMaterialsProgramKeepsTheAlphaTestAndOnlyItsInputs) {
  auto built = facet::test::buildText(kLeaf, "leaf.mat", withShadows({Tier::Reference, Tier::Mid}));
  ASSERT_TRUE(built);
  const pkg::Package& p = built->package;
  const std::string vertex = glsl(p, "mid.depth", pkg::Stage::Vertex);
  const std::string fragment = glsl(p, "mid.depth", pkg::Stage::Fragment);
  EXPECT_NE(vertex.find("in highp vec2 a_uv1;"), std::string::npos) << vertex;
  EXPECT_NE(vertex.find("out highp vec2 v_uv1;"), std::string::npos) << vertex;
  for (const char* absent : {"a_uv0", "a_color", "a_normal", "v_normal"})
    EXPECT_EQ(vertex.find(absent), std::string::npos) << absent << " in\n" << vertex;
  EXPECT_NE(fragment.find("precision mediump float;"), std::string::npos);
  EXPECT_NE(fragment.find("texture(facet_material_cut,"), std::string::npos) << fragment;
  EXPECT_NE(fragment.find("<0.4)discard;"), std::string::npos) << fragment;
  for (const char* absent : {"texture(facet_material_albedo", "params.tint", "v_color", "fragColor"})
    EXPECT_EQ(fragment.find(absent), std::string::npos) << absent << " in\n" << fragment;
  EXPECT_NE(glsl(p, "reference.depth", pkg::Stage::Fragment).find("precision highp float;"), std::string::npos);
}

// What the shadow pass cannot give alpha is a compile error naming the input, only when shadows
// are built.
TEST(DepthPrograms, AnAlphaReadingTheNormalIsAnErrorOnlyWhenShadowsAreBuilt) {
  const std::string text = "material fern { blending masked(0.5)\n surface { alpha = vertex.normal.y } }\n";
  facet::compiler::BuildOptions plain;
  plain.tiers = {Tier::High};
  EXPECT_TRUE(facet::test::buildText(text, "fern.mat", plain));
  facet::ir::SourceFile file{"fern.mat", text};
  facet::ir::Diagnostics diags(file);
  auto material = facet::ir::compileSource(file, diags);
  ASSERT_TRUE(material) << diags.format();
  facet::compiler::BuildError error;
  EXPECT_FALSE(facet::compiler::buildMaterial(*material, withShadows({Tier::High}), &error));
  EXPECT_EQ(error.message,
            "masked material 'fern': its alpha reads vertex.normal, which the shadow pass's depth-only program does "
            "not have (it interpolates vertex.uv0, vertex.uv1, vertex.color and vertex.worldPosition); make alpha "
            "independent of it, or build without shadows");
}

// The runtime's loader takes them (SPIR-V validated and reflected against an interface with no
// frame textures and no colour target), and refuses a depth-only program that writes a colour.
TEST(DepthPrograms, TheLoaderChecksThemAgainstAnInterfaceWithoutAColourTarget) {
  for (const std::string& text :
       {facet::test::readText(facet::test::examplePath("materials/red_plastic.mat")), std::string(kLeaf)}) {
    auto built = facet::test::buildText(text, "m.mat", withShadows({Tier::Mid}));
    ASSERT_TRUE(built);
    const std::vector<uint8_t> bytes = pkg::write(built->package);
    std::string error;
    auto material = facet::runtime::LoadedMaterial::loadFromMemory(bytes, built->package.material.name, &error);
    ASSERT_TRUE(material) << error;
    auto program = material->program("mid.depth", &error);
    ASSERT_TRUE(program) << error;
    ASSERT_TRUE(program->interface);
    EXPECT_TRUE(program->interface->depthOnly);
    EXPECT_FALSE(program->interface->shadowReceiver);
    for (const auto& s : program->interface->samplers)
      EXPECT_EQ(s.name.rfind("facet_material_", 0), 0u) << s.name << " bound for a depth-only program";
  }

  // A package built without shadows has none, and says which variants it has.
  facet::compiler::BuildOptions plain;
  plain.tiers = {Tier::Mid};
  auto without = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"), plain);
  ASSERT_TRUE(without);
  {
    const std::vector<uint8_t> bytes = pkg::write(without->package);
    std::string error;
    auto material = facet::runtime::LoadedMaterial::loadFromMemory(bytes, "red_plastic", &error);
    ASSERT_TRUE(material) << error;
    EXPECT_FALSE(material->program("mid.depth", &error));
    EXPECT_NE(error.find("mid.depth"), std::string::npos) << error;
  }

  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"), withShadows({Tier::Mid}));
  ASSERT_TRUE(built);
  facet::compiler::StageSources colour;
  colour.vertex =
      "#version 310 es\nlayout(location = 0) in highp vec3 a_position;\n"
      "void main() { gl_Position = vec4(a_position, 1.0); }\n";
  colour.fragment =
      "#version 310 es\nprecision mediump float;\nlayout(location = 0) out vec4 fragColor;\n"
      "void main() { fragColor = vec4(1.0); }\n";
  facet::compiler::SpirvStages spirv;
  std::string log;
  ASSERT_TRUE(facet::compiler::compileToSpirv(colour, &spirv, &log)) << log;
  for (pkg::Variant& v : built->package.variants)
    if (v.key == "mid.depth")
      for (pkg::Shader& s : v.shaders)
        if (s.stage == pkg::Stage::Fragment && s.target == pkg::Target::Spirv) {
          s.code.resize(spirv.fragment.size() * 4);
          std::memcpy(s.code.data(), spirv.fragment.data(), s.code.size());
        }
  const std::vector<uint8_t> bytes = pkg::write(built->package);
  std::string error;
  auto material = facet::runtime::LoadedMaterial::loadFromMemory(bytes, "red_plastic", &error);
  ASSERT_TRUE(material) << error;
  EXPECT_FALSE(material->program("mid.depth", &error));
  EXPECT_EQ(error,
            "material 'red_plastic' variant mid.depth: the fragment shader (SPIR-V) writes output 'fragColor'; the "
            "shadow pass, which draws the depth-only program, has no colour target");
}

// The vertex-stage slope bias (docs/shadows.md, "Bias"): `<tier>.depth.slope`, built beside
// `<tier>.depth` only when asked; its vertex stage reads the normal and adds the per-view constant
// times tan θ to the clip depth, a masked material's keeps its alpha test; the loader takes it.
TEST(DepthPrograms, TheVertexSlopeBiasProgramIsBuiltOnlyWhenAskedAndReadsTheNormal) {
  auto key = VariantKey::parse("mid.depth.slope");
  ASSERT_TRUE(key);
  EXPECT_TRUE(key->depthOnly);
  EXPECT_TRUE(key->vertexSlopeBias);
  EXPECT_EQ(key->toString(), "mid.depth.slope");
  EXPECT_TRUE(*key == facet::permutations::depthKey(Tier::Mid, true));
  for (const char* bad : {"mid.depth.slope.sh1", "mid.depth.slopes", "mid.dir1.slope", "mid.depth.depth"})
    EXPECT_FALSE(VariantKey::parse(bad)) << bad;
  EXPECT_EQ(names(enumerate({true}, {Tier::High}, nullptr, {0}, {0, 1})),
            (std::vector<std::string>{"high.dir0", "high.dir1", "high.dir1.sh1", "high.depth"}));
  EXPECT_EQ(names(enumerate({true}, {Tier::High}, nullptr, {0}, {0, 1}, false, true)),
            (std::vector<std::string>{"high.dir0", "high.dir1", "high.dir1.sh1", "high.depth", "high.depth.slope"}));
  // Without shadows there is no depth-only program to give a slope bias.
  EXPECT_EQ(names(enumerate({true}, {Tier::High}, nullptr, {0}, {0}, false, true)),
            (std::vector<std::string>{"high.dir0", "high.dir1"}));
  // A scene asks for exactly the one its slope stage draws with.
  facet::permutations::SceneNeeds scene{{facet::permutations::depthKey(Tier::Low, true)}};
  EXPECT_EQ(names(enumerate({true}, {Tier::Low}, &scene)), (std::vector<std::string>{"low.depth.slope"}));

  facet::compiler::BuildOptions options = withShadows({Tier::Mid});
  options.vertexSlopeBias = true;
  for (const std::string& text :
       {facet::test::readText(facet::test::examplePath("materials/red_plastic.mat")), std::string(kLeaf)}) {
    auto built = facet::test::buildText(text, "m.mat", options);
    ASSERT_TRUE(built);
    const pkg::Package& p = built->package;
    const std::string vertex = glsl(p, "mid.depth.slope", pkg::Stage::Vertex);
    for (const char* line : {"in highp vec3 a_normal;", "gl_Position=frame.viewProjection*worldPosition;",
                             "gl_Position.z+=frame.lightDirection.w*slope;"})
      EXPECT_NE(vertex.find(line), std::string::npos) << line << " in\n" << vertex;
    EXPECT_EQ(glsl(p, "mid.depth", pkg::Stage::Vertex).find("a_normal"), std::string::npos);
    // The fragment stage is the plain program's: the same alpha test (or none).
    EXPECT_EQ(glsl(p, "mid.depth.slope", pkg::Stage::Fragment), glsl(p, "mid.depth", pkg::Stage::Fragment));
    const std::vector<uint8_t> bytes = pkg::write(p);
    std::string error;
    auto material = facet::runtime::LoadedMaterial::loadFromMemory(bytes, p.material.name, &error);
    ASSERT_TRUE(material) << error;
    auto program = material->program("mid.depth.slope", &error);
    ASSERT_TRUE(program) << error;
    ASSERT_TRUE(program->interface);
    EXPECT_TRUE(program->interface->depthOnly);
  }
  auto leaf = facet::test::buildText(kLeaf, "leaf.mat", options);
  ASSERT_TRUE(leaf);
  EXPECT_NE(glsl(leaf->package, "mid.depth.slope", pkg::Stage::Fragment).find("<0.4)discard;"), std::string::npos);
}
