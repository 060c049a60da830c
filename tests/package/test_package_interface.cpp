// A package's declared meaning against its shaders (facet/package/program_interface.h): hostile packages
// written by package::write, so checksum-valid and well formed, whose shaders are in the wrong
// slot or read another interface than the tables declare. Each is refused when its variant is
// loaded — the SPIR-V by LoadedMaterial::program, the GLSL ES by the GL backend before any draw —
// with a message naming material, variant and stage. Before these checks Vulkan drew them (reading
// past the parameter block, or an unbound texture) or failed without naming either, and a
// stage-swapped module crashed the validation layer.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "facet/compiler/glslang_backend.h"
#include "facet/package/package.h"
#include "facet/runtime/material.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

namespace pkg = facet::package;
using pkg::Stage;
using pkg::Target;

pkg::Package examplePackage(const std::string& material) {
  static const std::string dir = facet::test::writeExamplePackages("package-interface");
  pkg::ReadResult r = pkg::readFile(dir + "/" + material + ".matpkg");
  EXPECT_TRUE(r.package) << r.error;
  return r.package.value_or(pkg::Package{});
}

pkg::Shader& shader(pkg::Package& p, const std::string& key, Stage stage, Target target) {
  for (pkg::Variant& v : p.variants)
    if (v.key == key)
      for (pkg::Shader& s : v.shaders)
        if (s.stage == stage && s.target == target) return s;
  ADD_FAILURE() << "no " << pkg::toString(stage) << " " << pkg::toString(target) << " shader in " << key;
  static pkg::Shader none;
  return none;
}

// What LoadedMaterial::program says about one variant of `p` ("" when it loads).
std::string programError(const pkg::Package& p, const std::string& key) {
  const std::vector<uint8_t> bytes = pkg::write(p);
  std::string error;
  auto material = facet::runtime::LoadedMaterial::loadFromMemory(bytes, p.material.name, &error);
  if (!material) return error;
  return material->program(key, &error) ? "" : error;
}

// The package as a GL-only build would ship it: no SPIR-V (nor MSL), so nothing in the core sees
// the shaders' interface and the GL backend's own check must.
pkg::Package withoutSpirv(pkg::Package p) {
  for (pkg::Variant& v : p.variants)
    std::erase_if(v.shaders, [](const pkg::Shader& s) { return s.target != Target::GlslEs300; });
  return p;
}

// Draws `scene` at `tier` with `p` on a GL backend; the error, or "" when it drew. A refused
// program must fail the frame before its first draw, so debug output stays clean.
std::string glDrawError(const pkg::Package& p, const std::string& sceneFile, const std::string& tier) {
  const std::string dir = facet::test::scratchDir("package-interface-gl");
  std::string error;
  EXPECT_TRUE(pkg::writeFile(dir + "/" + p.material.name + ".matpkg", pkg::write(p), &error)) << error;
  auto scene = facet::runtime::loadScene(facet::test::examplePath(sceneFile), &error);
  EXPECT_TRUE(scene) << error;
  if (!scene) return error;
  scene->tier = tier;
  scene->width = 64;
  scene->height = 64;
  auto frame = facet::runtime::SceneFrame::prepare(*scene, dir, &error);
  if (!frame) return "prepare: " + error;
  static auto backend = facet::runtime::createGlBackend(&error);
  EXPECT_TRUE(backend) << error;
  if (!backend) return error;
  facet::runtime::FrameResult result;
  const bool drew = backend->render(frame->frame(), &result, &error);
  EXPECT_TRUE(backend->validationErrors().empty()) << backend->validationErrors().front();
  return drew ? "" : error;
}

std::vector<uint8_t> bytesOf(const std::vector<uint32_t>& words) {
  std::vector<uint8_t> out(words.size() * 4);
  std::memcpy(out.data(), words.data(), out.size());
  return out;
}

// Hand-written shaders for interfaces the compiler never writes, as SPIR-V (GLSL ES 3.10 for
// Vulkan) and as GLSL ES 3.00 text: `fragmentDeclarations` and `fragmentBody` go into a
// fragment shader writing fragColor; the vertex shader reads a_position at location 0.
struct HandWritten {
  std::vector<uint8_t> vertexSpirv, fragmentSpirv, vertexGlsl, fragmentGlsl;
};
HandWritten handWritten(const std::string& vulkanDeclarations, const std::string& glDeclarations,
                        const std::string& body, const std::string& vertexInput = "highp vec3 a_position",
                        const std::string& glBody = "") {
  const std::string vertexBody = "void main() { gl_Position = vec4(a_position.xyz, 1.0); }\n";
  const std::string fragmentHead = "precision mediump float;\n";
  const std::string fragmentBody = "void main() { fragColor = " + body + "; }\n";
  const std::string glFragmentBody = "void main() { fragColor = " + (glBody.empty() ? body : glBody) + "; }\n";
  facet::compiler::StageSources vulkan;
  vulkan.vertex = "#version 310 es\nlayout(location = 0) in " + vertexInput + ";\n" + vertexBody;
  vulkan.fragment = "#version 310 es\n" + fragmentHead + vulkanDeclarations +
                    "layout(location = 0) out vec4 fragColor;\n" + fragmentBody;
  facet::compiler::SpirvStages spirv;
  std::string log;
  EXPECT_TRUE(facet::compiler::compileToSpirv(vulkan, &spirv, &log)) << log;
  HandWritten out;
  out.vertexSpirv = bytesOf(spirv.vertex);
  out.fragmentSpirv = bytesOf(spirv.fragment);
  const std::string glVertex = "#version 300 es\nlayout(location = 0) in " + vertexInput + ";\n" + vertexBody;
  const std::string glFragment = "#version 300 es\n" + fragmentHead + glDeclarations +
                                 "layout(location = 0) out vec4 fragColor;\n" + glFragmentBody;
  out.vertexGlsl.assign(glVertex.begin(), glVertex.end());
  out.fragmentGlsl.assign(glFragment.begin(), glFragment.end());
  return out;
}

void install(pkg::Package& p, const std::string& key, const HandWritten& code) {
  shader(p, key, Stage::Vertex, Target::Spirv).code = code.vertexSpirv;
  shader(p, key, Stage::Fragment, Target::Spirv).code = code.fragmentSpirv;
  shader(p, key, Stage::Vertex, Target::GlslEs300).code = code.vertexGlsl;
  shader(p, key, Stage::Fragment, Target::GlslEs300).code = code.fragmentGlsl;
}

// `from`'s fragment shaders of variant `fromKey`, both targets, in `to`'s variant `toKey`.
void transplantFragment(pkg::Package& to, const std::string& toKey, pkg::Package from, const std::string& fromKey) {
  for (Target t : {Target::Spirv, Target::GlslEs300})
    shader(to, toKey, Stage::Fragment, t).code = shader(from, fromKey, Stage::Fragment, t).code;
}

void expectContains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "expected '" << part << "' in: " << text;
}

}  // namespace

// Vertex and fragment SPIR-V of one variant swapped: each module is valid on its own, so
// spirv-val passed it, and lavapipe failed pipeline creation with VK_ERROR_UNKNOWN (the validation
// layer crashed). The entry point's execution model is now compared with the slot's stage.
TEST(PackageInterface, StageSwappedSpirvIsRefusedNamingMaterialVariantAndStage) {
  pkg::Package p = examplePackage("red_plastic");
  ASSERT_EQ(programError(p, "high.dir1"), "");
  std::swap(shader(p, "high.dir1", Stage::Vertex, Target::Spirv).code,
            shader(p, "high.dir1", Stage::Fragment, Target::Spirv).code);
  const std::string error = programError(p, "high.dir1");
  expectContains(error, "material 'red_plastic' variant high.dir1: the vertex shader (SPIR-V) is a fragment shader");
  EXPECT_EQ(programError(p, "high.dir0"), "") << "the other variants still load";

  // Only the fragment slot holding a vertex shader: the same check, that stage named.
  pkg::Package twice = examplePackage("red_plastic");
  shader(twice, "mid.dir0", Stage::Fragment, Target::Spirv).code =
      shader(twice, "mid.dir0", Stage::Vertex, Target::Spirv).code;
  expectContains(programError(twice, "mid.dir0"), "variant mid.dir0: the fragment shader (SPIR-V) is a vertex shader");
}

// The preshader section dropped: the shaders read the 64-byte preshaded block, the runtime binds
// the 32 bytes of parameters. Vulkan read 32 bytes past the buffer; GL refused at the draw without
// naming the material.
TEST(PackageInterface, DroppedPreshaderIsABlockSizeErrorOnBothBackends) {
  pkg::Package p = examplePackage("red_plastic");
  ASSERT_EQ(p.material.paramBlockSize, 32u);
  p.preshader = {};
  expectContains(
      programError(p, "high.dir1"),
      "material 'red_plastic' variant high.dir1: the fragment shader (SPIR-V) reads MaterialParams as 76 bytes, "
      "but the runtime binds 32");
  expectContains(
      glDrawError(withoutSpirv(p), "scenes/sphere.json", "high"),
      "draw 0: material 'red_plastic' variant high.dir1: the fragment shader (GLSL ES) reads MaterialParams as 80 "
      "bytes, but the runtime binds 32");
}

// The lut tier's table: dropped, the low tier samples an unbound binding (Vulkan bound a 1x1
// dummy and drew); the same bytes as 64 x 128, the shaders address texels that are not there;
// listed for a variant that does not sample it, the package's word disagrees with its code.
TEST(PackageInterface, SpecularTableMustBeShippedAsTheShadersSampleIt) {
  const pkg::Package good = examplePackage("painted_tiles");
  ASSERT_EQ(good.textures.size(), 1u);
  ASSERT_EQ(programError(good, "low.dir1"), "");
  pkg::Package dropped = good;
  dropped.textures.clear();
  expectContains(programError(dropped, "low.dir1"),
                 "material 'painted_tiles' variant low.dir1: the fragment shader (SPIR-V) samples sampler "
                 "'facet_specularLut' (set 1 binding 1), which the variant's draws do not bind (the package ships no "
                 "facet_specularLut for it)");
  expectContains(
      glDrawError(withoutSpirv(dropped), "scenes/tiles.json", "low"),
      "material 'painted_tiles' variant low.dir1: the fragment shader (GLSL ES) samples sampler 'facet_specularLut', "
      "which the variant's draws do not bind");

  for (auto [width, height] : {std::pair{64u, 128u}, std::pair{256u, 32u}}) {
    pkg::Package reshaped = good;
    reshaped.textures[0].width = width;
    reshaped.textures[0].height = height;
    expectContains(programError(reshaped, "low.dir1"), "painted_tiles: texture 'facet_specularLut' is " +
                                                           std::to_string(width) + "x" + std::to_string(height) +
                                                           "; the shaders address it as 128x64");
  }

  pkg::Package unsampled = good;
  ASSERT_EQ(unsampled.variants[6].key, "low.dir0");
  unsampled.textures[0].variants = {6, 7};
  expectContains(
      programError(unsampled, "low.dir0"),
      "material 'painted_tiles' variant low.dir0: the package ships texture 'facet_specularLut' for this variant, "
      "which neither shader samples");
}

// Shaders of another variant or another material in a variant's slots: what differs is named.
TEST(PackageInterface, AFragmentShaderFromAnotherVariantOrMaterialIsRefused) {
  // mid.dir1's fragment reads the per-vertex diffuse light that high.dir1's vertex shader does not write.
  pkg::Package p = examplePackage("red_plastic");
  transplantFragment(p, "high.dir1", p, "mid.dir1");
  const std::string spirvError = programError(p, "high.dir1");
  expectContains(spirvError, "material 'red_plastic' variant high.dir1: the fragment shader (SPIR-V) reads input");
  expectContains(spirvError, "which the vertex shader (SPIR-V) does not write");
  // The GL linker matches the stages itself; its refusal now names the material and variant.
  expectContains(glDrawError(withoutSpirv(p), "scenes/sphere.json", "high"),
                 "material 'red_plastic' variant high.dir1: ");

  // painted_tiles' low.dir1 fragment in low.dir0, which the package ships no table for.
  pkg::Package tiles = examplePackage("painted_tiles");
  shader(tiles, "low.dir0", Stage::Fragment, Target::Spirv).code =
      shader(tiles, "low.dir1", Stage::Fragment, Target::Spirv).code;
  expectContains(programError(tiles, "low.dir0"),
                 "variant low.dir0: the fragment shader (SPIR-V) samples sampler 'facet_specularLut'");

  // brushed_gold's fragment shader in red_plastic: the same stage interface and a block of the
  // same offsets and types (a colour at 0, a float at 12 and at 16), another material's names.
  pkg::Package impostor = examplePackage("red_plastic");
  transplantFragment(impostor, "high.dir1", examplePackage("brushed_gold"), "high.dir1");
  const std::string layoutError = programError(impostor, "high.dir1");
  expectContains(layoutError,
                 "material 'red_plastic' variant high.dir1: the fragment shader (SPIR-V) MaterialParams member");
  expectContains(layoutError, "'tint' (vec3, bytes 0..12) does not match parameter 'baseColor' (vec3, bytes 0..12)");
  const std::string glError = glDrawError(withoutSpirv(impostor), "scenes/sphere.json", "high");
  expectContains(glError,
                 "material 'red_plastic' variant high.dir1: the fragment shader (GLSL ES) MaterialParams member");
  expectContains(glError, "'tint' (vec3, bytes 0..12) does not match parameter 'baseColor' (vec3, bytes 0..12)");
}

// Interfaces the compiler never writes, in hand-written shaders: a 2D sampler where the runtime
// binds a cube map, a resource the runtime never binds, a vertex input of the wrong width, a
// second colour output. The same check on both backends' reflections.
TEST(PackageInterface, HandWrittenInterfacesAreCheckedOnBothBackends) {
  struct Case {
    HandWritten code;
    std::string spirv, gl;  // expected in the message, after "the <stage> shader (<code>) "
  };
  const Case cases[] = {
      {handWritten("layout(set = 1, binding = 2) uniform sampler2D facet_environment;\n",
                   "uniform sampler2D facet_environment;\n", "texture(facet_environment, vec2(0.5))"),
       "fragment shader (SPIR-V) samples sampler 'facet_environment' (set 1 binding 2) as a 2D texture; the runtime "
       "binds "
       "a cube map there",
       "fragment shader (GLSL ES) samples sampler 'facet_environment' as a 2D texture; the runtime binds a cube map "
       "there"},
      {handWritten("layout(set = 1, binding = 5) uniform sampler2D stray;\n", "uniform sampler2D stray;\n",
                   "texture(stray, vec2(0.5))"),
       "fragment shader (SPIR-V) samples sampler 'stray' (set 1 binding 5), which the variant's draws do not bind",
       "fragment shader (GLSL ES) samples sampler 'stray', which the variant's draws do not bind"},
      {handWritten("layout(std430, set = 0, binding = 4) buffer Extra { vec4 data[]; } extra;\n",
                   "uniform vec4 extra;\n", "extra.data[0]"),
       "fragment shader (SPIR-V) declares storage buffer 'Extra', which the runtime does not bind", ""},
      {handWritten("", "uniform vec4 extra;\n", "vec4(1.0)",
                   "highp vec3 a_position;\nlayout(location = 4) in highp vec3 a_color"),
       "vertex shader (SPIR-V) reads vertex input 'a_color' at location 4 as vec3; the runtime supplies a_color there "
       "as vec4",
       ""},
      {handWritten("", "uniform vec4 extra;\n", "vec4(1.0)",
                   "highp vec3 a_position;\nlayout(location = 1) in highp vec3 a_bent"),
       "vertex shader (SPIR-V) reads vertex input 'a_bent' at location 1, where the runtime supplies a_normal", ""},
      {handWritten("layout(location = 1) out vec4 second;\n", "", "vec4(1.0)"),
       "fragment shader (SPIR-V) writes output 'second' (vec4 at location 1); the forward pass has one colour target, "
       "a "
       "vec4 at location 0",
       ""},
  };
  for (const Case& c : cases) {
    pkg::Package p = examplePackage("red_plastic");
    install(p, "high.dir1", c.code);
    expectContains(programError(p, "high.dir1"), "material 'red_plastic' variant high.dir1: the " + c.spirv);
    if (!c.gl.empty())
      expectContains(glDrawError(withoutSpirv(p), "scenes/sphere.json", "high"),
                     "material 'red_plastic' variant high.dir1: the " + c.gl);
  }
  // GL: an attribute at another attribute's location reads that attribute's data.
  pkg::Package moved = examplePackage("red_plastic");
  install(moved, "high.dir1",
          handWritten("", "", "vec4(1.0)", "highp vec3 unused;\nlayout(location = 1) in highp vec3 a_position"));
  expectContains(
      glDrawError(withoutSpirv(moved), "scenes/sphere.json", "high"),
      "the vertex shader (GLSL ES) reads vertex input 'a_position' at location 1, where the runtime supplies a_normal");
  // GL: a uniform outside the ABI's blocks, which no draw sets.
  pkg::Package p = examplePackage("red_plastic");
  install(p, "high.dir1", handWritten("", "uniform vec4 extra;\n", "vec4(1.0)", "highp vec3 a_position", "extra"));
  expectContains(glDrawError(withoutSpirv(p), "scenes/sphere.json", "high"),
                 "the fragment shader (GLSL ES) declares uniform 'extra' outside the ABI's blocks, which the runtime "
                 "does not bind");
}

// The checks cost nothing on what the compiler writes: every variant of every example material
// loads, and draws on GL (where the linked program is checked too).
TEST(PackageInterface, EveryExampleVariantPassesTheChecks) {
  for (const char* name : {"red_plastic", "painted_tiles", "brushed_gold", "banded_ceramic"}) {
    const pkg::Package p = examplePackage(name);
    const std::vector<uint8_t> bytes = pkg::write(p);
    std::string error;
    auto material = facet::runtime::LoadedMaterial::loadFromMemory(bytes, name, &error);
    ASSERT_TRUE(material) << error;
    EXPECT_TRUE(material->checkEveryVariant(&error)) << error;
    for (const pkg::Variant& v : p.variants) {
      auto program = material->program(v.key, &error);
      ASSERT_TRUE(program) << error;
      ASSERT_TRUE(program->interface);
      EXPECT_EQ(program->interface->variant, v.key);
    }
  }
  // Point and spot lights read the lut tier's table too: the compiler ships it for a low variant
  // lit by them alone (it used to list the sun's variants only, and such a variant drew its
  // lights' highlights from an unbound table).
  facet::compiler::BuildOptions lamps;
  lamps.pointLightCounts = {0, 2};
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"), lamps);
  ASSERT_TRUE(built);
  const std::vector<uint8_t> bytes = pkg::write(built->package);
  std::string error;
  auto material = facet::runtime::LoadedMaterial::loadFromMemory(bytes, "red_plastic", &error);
  ASSERT_TRUE(material) << error;
  EXPECT_TRUE(material->checkEveryVariant(&error)) << error;

  for (const char* tier : {"reference", "high", "mid", "low"}) {
    EXPECT_EQ(glDrawError(examplePackage("painted_tiles"), "scenes/tiles.json", tier), "") << tier;
    EXPECT_EQ(glDrawError(examplePackage("red_plastic"), "scenes/sphere.json", tier), "") << tier;
  }
}
