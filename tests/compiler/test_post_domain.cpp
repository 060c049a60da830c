// The compiler's post domain: every form of the post pass comes out of the same pipeline as
// materials, the fetch forms read the pixel in the API's own way, and an effect that is off is
// absent from the shaders.
#include <gtest/gtest.h>

#include "facet/abi/shader_abi.h"
#include "facet/compiler/post.h"
#include "facet/compiler/spirv_tools_backend.h"

namespace {

using namespace facet::compiler;

PostShaders build(const PostEffects& effects) {
  PostShaders shaders;
  std::string error;
  EXPECT_TRUE(buildPostShaders(effects, &shaders, &error)) << error;
  return shaders;
}

bool contains(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

TEST(PostDomain, EveryFormIsBuiltForEveryTarget) {
  const PostShaders s = build({});
  EXPECT_EQ(postVariantKey(s.effects), "aces");
  for (const PostStage* stage : {&s.vertex, &s.sampledFragment, &s.fetchFragment}) {
    std::string log;
    EXPECT_TRUE(validateSpirv(stage->spirv, &log)) << log;
    EXPECT_TRUE(contains(stage->glslEs, "#version 300 es"));
    EXPECT_TRUE(contains(stage->msl, "main0"));
  }
}

TEST(PostDomain, FetchFormsReadTheirOwnPixelInEachApi) {
  const PostShaders s = build({});
  // Vulkan: a subpass input.
  EXPECT_TRUE(contains(disassembleSpirv(s.fetchFragment.spirv), "SubpassData"));
  EXPECT_FALSE(contains(disassembleSpirv(s.sampledFragment.spirv), "SubpassData"));
  // GLES: the framebuffer-fetch extension, HDR as an inout colour output 0, LDR at 1.
  EXPECT_TRUE(contains(s.fetchFragment.glslEs, "#extension GL_EXT_shader_framebuffer_fetch : require"));
  EXPECT_TRUE(contains(s.fetchFragment.glslEs, "#define FACET_POST_FRAMEBUFFER_FETCH"));
  EXPECT_FALSE(contains(s.sampledFragment.glslEs, "#extension GL_EXT_shader_framebuffer_fetch"));
  // Metal: HDR is a [[color(0)]] input, LDR the [[color(1)]] output.
  EXPECT_TRUE(contains(s.fetchFragment.msl, "hdrColor [[color(0)]]")) << s.fetchFragment.msl;
  EXPECT_TRUE(contains(s.fetchFragment.msl, "fragColor [[color(1)]]")) << s.fetchFragment.msl;
  EXPECT_FALSE(contains(s.sampledFragment.msl, "[[color(0)]])")) << s.sampledFragment.msl;
}

// The per-sample form (Vulkan's merged path under MSAA, portable form): a multisampled subpass
// input whose sample count is a specialization constant, read in a loop (no gl_SampleID, so the
// fragment stage runs once per pixel, not per sample); its GLSL ES 3.10 text loops over a
// sampler2DMS. Bloom variants have none (bloom runs the separate path).
TEST(PostDomain, ThePerSampleFormReadsEverySampleOfAMultisampledInput) {
  const PostShaders s = build({});
  std::string log;
  ASSERT_TRUE(validateSpirv(s.samplesFragment.spirv, &log)) << log;
  const std::string spirv = disassembleSpirv(s.samplesFragment.spirv);
  EXPECT_TRUE(contains(spirv, "SubpassData 0 0 1 2")) << spirv;  // depth 0, arrayed 0, MS 1
  EXPECT_TRUE(contains(spirv, "OpSpecConstant")) << spirv;
  EXPECT_TRUE(contains(spirv, "SpecId 0")) << spirv;
  EXPECT_FALSE(contains(spirv, "SampleId"));
  EXPECT_FALSE(contains(spirv, "SampleRateShading"));
  EXPECT_FALSE(contains(disassembleSpirv(s.fetchFragment.spirv), "SubpassData 0 0 1 2"));
  EXPECT_TRUE(contains(s.samplesFragment.glslEs, "#version 310 es"));
  EXPECT_TRUE(contains(s.samplesFragment.glslEs, "uniform mediump sampler2DMS hdrColor"));
  EXPECT_TRUE(s.samplesFragment.msl.empty());
  PostEffects bloom;
  bloom.bloom = true;
  EXPECT_TRUE(build(bloom).samplesFragment.spirv.empty());
}

TEST(PostDomain, AnEffectTurnedOffIsAbsentFromThePostShader) {
  const PostShaders on = build({});
  PostEffects noTonemap;
  noTonemap.toneCurve = ToneCurve::None;
  const PostShaders off = build(noTonemap);
  EXPECT_NE(postVariantKey(on.effects), postVariantKey(off.effects));
  // The chunk is not assembled in (its call sits in a preprocessor branch that is off), and
  // nothing of it reaches the compiled targets.
  const std::string definition = "vec3 tonemap_aces_fitted(vec3";
  EXPECT_TRUE(contains(on.sampledFragment.glslEs, definition));
  EXPECT_TRUE(contains(on.sampledFragment.glslEs, "#define FACET_POST_ACES"));
  for (const PostStage* stage : {&off.sampledFragment, &off.fetchFragment}) {
    EXPECT_FALSE(contains(stage->glslEs, definition)) << stage->glslEs;
    EXPECT_FALSE(contains(stage->glslEs, "#define FACET_POST_ACES")) << stage->glslEs;
    EXPECT_FALSE(contains(stage->msl, "tonemap_aces"));
  }
  // And it costs nothing: the optimized fragment is smaller without it.
  EXPECT_LT(off.sampledFragment.spirv.size(), on.sampledFragment.spirv.size());
}

TEST(PostDomain, KeysNameTheEffectsAndEachEffectOnlyItsOwnCode) {
  PostEffects neutral;
  neutral.toneCurve = ToneCurve::Neutral;
  PostEffects dithered = neutral;
  dithered.dither = true;
  const PostShaders n = build(neutral), d = build(dithered);
  EXPECT_EQ(postVariantKey(n.effects), "neutral");
  EXPECT_EQ(postVariantKey(d.effects), "neutral+dither");
  EXPECT_EQ(postVariantKey({}), "aces");
  for (const PostStage* stage : {&n.sampledFragment, &n.fetchFragment, &d.sampledFragment, &d.fetchFragment}) {
    EXPECT_TRUE(contains(stage->glslEs, "vec3 tonemap_khronos_neutral(vec3"));
    EXPECT_FALSE(contains(stage->glslEs, "vec3 tonemap_aces_fitted(vec3"));
  }
  EXPECT_FALSE(contains(n.sampledFragment.glslEs, "vec3 dither_triangular_8bit(vec3"));
  EXPECT_FALSE(contains(n.fetchFragment.glslEs, "#define FACET_POST_DITHER"));
  EXPECT_TRUE(contains(d.fetchFragment.glslEs, "#define FACET_POST_DITHER"));
  EXPECT_TRUE(contains(d.sampledFragment.glslEs, "dither_triangular_8bit(encoded, gl_FragCoord.xy)"));
  // The noise needs highp (pixel coordinates beyond fp16's integers): Metal computes it in float.
  EXPECT_TRUE(contains(d.sampledFragment.msl, "fract(")) << d.sampledFragment.msl;
  EXPECT_GT(d.sampledFragment.spirv.size(), n.sampledFragment.spirv.size());
  EXPECT_EQ(toneCurveFromString("neutral"), ToneCurve::Neutral);
  EXPECT_FALSE(toneCurveFromString("filmic"));
}

TEST(PostDomain, GeneratedRuntimeSourceDefinesPostShaders) {
  PostEffects neutral;
  neutral.toneCurve = ToneCurve::Neutral;
  PostStage fxaa;
  BloomStages bloom;
  std::string error;
  ASSERT_TRUE(buildFxaaShader(&fxaa, &error)) << error;
  ASSERT_TRUE(buildBloomShaders(&bloom, &error)) << error;
  const std::string cpp = postShadersCpp({build({}), build(neutral)}, fxaa, bloom);
  EXPECT_TRUE(contains(cpp, "const std::vector<PostShaders>& postVariants()"));
  EXPECT_TRUE(contains(cpp, "kFetchSpirv1"));
  EXPECT_TRUE(contains(cpp, "{{\"neutral\", false, false, false, false}, vs1,"));
  EXPECT_EQ(everyPostEffects().size(), 48u);  // 3 tone curves × grading × vignette × dither × bloom
  EXPECT_TRUE(contains(cpp, "const BloomShaders& bloomShaders()"));
  EXPECT_TRUE(contains(cpp, "bloom_downsample13(bloomSource"));
  EXPECT_TRUE(contains(cpp, "GL_EXT_shader_framebuffer_fetch"));
  EXPECT_TRUE(contains(cpp, "const FxaaShader& fxaaShader()"));
  EXPECT_TRUE(contains(cpp, "fxaa_console(toneMapped"));
}

}  // namespace

TEST(PostDomain, GradingAndVignetteAreCompiledOutWhenOffAndBoundFromTheAbiWhenOn) {
  PostEffects graded;
  graded.colorGrading = true;
  PostEffects vignetted;
  vignetted.vignette = true;
  const PostShaders off = build({}), g = build(graded), v = build(vignetted);
  EXPECT_EQ(postVariantKey(g.effects), "aces+grading");
  EXPECT_EQ(postVariantKey({ToneCurve::Neutral, true, true, true}), "neutral+grading+vignette+dither");
  // Off: no LUT sampler, no 3D image type, no uniform block, in any form or target (the
  // template's calls sit in preprocessor branches that are off).
  for (const PostStage* stage : {&off.sampledFragment, &off.fetchFragment, &v.sampledFragment, &v.fetchFragment}) {
    EXPECT_FALSE(contains(stage->glslEs, "sampler3D")) << stage->glslEs;
    EXPECT_FALSE(contains(stage->glslEs, "vec3 grade_color_lut("));
    EXPECT_FALSE(contains(stage->glslEs, "#define FACET_POST_COLOR_GRADING"));
    EXPECT_FALSE(contains(disassembleSpirv(stage->spirv), " 3D ")) << "no 3D image type";
    EXPECT_FALSE(contains(stage->msl, "texture3d"));
  }
  for (const PostStage* stage : {&off.sampledFragment, &off.fetchFragment, &g.sampledFragment, &g.fetchFragment}) {
    EXPECT_FALSE(contains(stage->glslEs, "PostUniforms"));
    EXPECT_FALSE(contains(stage->glslEs, "float vignette_factor("));
    EXPECT_FALSE(contains(stage->glslEs, "#define FACET_POST_VIGNETTE"));
    EXPECT_FALSE(contains(stage->msl, "PostUniforms"));
  }
  // On: the sampler and the block at shader_abi.h's binding in SPIR-V and Metal, by name in GLSL ES.
  for (const PostStage* stage : {&g.sampledFragment, &g.fetchFragment}) {
    EXPECT_TRUE(contains(stage->glslEs, "uniform mediump sampler3D facet_colorLut;"));
    EXPECT_TRUE(contains(disassembleSpirv(stage->spirv), "OpDecorate %facet_colorLut Binding 1"))
        << disassembleSpirv(stage->spirv);
    EXPECT_TRUE(contains(stage->msl, "texture3d<float> facet_colorLut [[texture(1)]]")) << stage->msl;
  }
  for (const PostStage* stage : {&v.sampledFragment, &v.fetchFragment}) {
    EXPECT_TRUE(contains(stage->glslEs, "layout(std140) uniform PostUniforms"));
    EXPECT_TRUE(contains(disassembleSpirv(stage->spirv), "OpDecorate %post Binding 3"))
        << disassembleSpirv(stage->spirv);
    EXPECT_TRUE(contains(stage->msl, "constant PostUniforms& post [[buffer(3)]]")) << stage->msl;
  }
  EXPECT_LT(off.sampledFragment.spirv.size(), g.sampledFragment.spirv.size());
  EXPECT_LT(off.sampledFragment.spirv.size(), v.sampledFragment.spirv.size());
  EXPECT_EQ(postMslBindings({}).size(), 1u);
  EXPECT_EQ(postMslBindings({ToneCurve::Aces, false, true, true}).size(), 3u);
}

// Bloom off is compiled out (no bloom sampler, chunk or block); on, the chain's image and the block
// sit at shader_abi.h's bindings, and the composite runs before the tone curve.
TEST(PostDomain, BloomIsCompiledOutWhenOffAndBoundFromTheAbiWhenOn) {
  PostEffects bloomed;
  bloomed.bloom = true;
  const PostShaders off = build({}), b = build(bloomed);
  EXPECT_EQ(postVariantKey(b.effects), "aces+bloom");
  for (const PostStage* stage : {&off.sampledFragment, &off.fetchFragment, &off.upscaledFragment}) {
    EXPECT_FALSE(contains(stage->glslEs, "sampler2D facet_bloom"));
    EXPECT_FALSE(contains(stage->glslEs, "vec3 bloom_composite("));
    EXPECT_FALSE(contains(stage->glslEs, "#define FACET_POST_BLOOM"));
    EXPECT_FALSE(contains(disassembleSpirv(stage->spirv), "facet_bloom"));
    EXPECT_FALSE(contains(stage->msl, "facet_bloom"));
  }
  for (const PostStage* stage : {&b.sampledFragment, &b.upscaledFragment}) {
    EXPECT_TRUE(contains(stage->glslEs, "uniform mediump sampler2D facet_bloom;"));
    EXPECT_TRUE(contains(stage->glslEs, "layout(std140) uniform PostUniforms"));
    EXPECT_TRUE(contains(disassembleSpirv(stage->spirv), "OpDecorate %facet_bloom Binding 2"))
        << disassembleSpirv(stage->spirv);
    EXPECT_TRUE(contains(stage->msl, "facet_bloom [[texture(2)]]")) << stage->msl;
    const size_t composite = stage->glslEs.find("hdr = bloom_composite(");
    ASSERT_NE(composite, std::string::npos);
    EXPECT_LT(composite, stage->glslEs.find("tonemap_aces_fitted(hdr)"));
  }
  EXPECT_EQ(postMslBindings(bloomed).size(), 3u);
  BloomStages chain;
  std::string error;
  ASSERT_TRUE(buildBloomShaders(&chain, &error)) << error;
  EXPECT_FALSE(contains(chain.downsample.glslEs, "uniform PostUniforms"));
  EXPECT_TRUE(contains(chain.downsampleThreshold.glslEs, "layout(std140) uniform PostUniforms"));
  EXPECT_TRUE(contains(chain.upsample.glslEs, "bloom_tent9(bloomSource"));
  EXPECT_TRUE(contains(chain.vertex.glslEs, "out highp vec2 bloomUv;"));
}

// The environment background: built for every target, reading the environment at the ABI's slot
// with an explicit level (no derivative: the face changes under a pixel at cube edges), its
// parameters from the MaterialParams slot, and written into the runtime's generated source.
TEST(PostDomain, TheBackgroundIsBuiltForEveryTargetAndBoundFromTheAbi) {
  BackgroundStages background;
  std::string error;
  ASSERT_TRUE(buildBackgroundShaders(&background, &error)) << error;
  for (const PostStage* stage : {&background.vertex, &background.fragment}) {
    EXPECT_FALSE(stage->spirv.empty());
    EXPECT_TRUE(contains(stage->glslEs, "#version 300 es"));
    EXPECT_TRUE(contains(stage->glslEs, "uniform MaterialParams"));
    EXPECT_TRUE(contains(stage->msl, "[[buffer(" + std::to_string(facet::abi::kMaterialBinding) + ")]]"));
  }
  EXPECT_TRUE(contains(background.fragment.glslEs, "uniform mediump samplerCube facet_environment;"));
  EXPECT_TRUE(contains(background.fragment.glslEs, "textureLod(facet_environment"));
  EXPECT_FALSE(contains(background.fragment.glslEs, "dFd"));
  EXPECT_TRUE(
      contains(background.fragment.msl, "[[texture(" + std::to_string(facet::abi::kEnvironmentBinding) + ")]]"));
  EXPECT_TRUE(contains(background.vertex.msl, "[[buffer(" + std::to_string(facet::abi::kObjectBinding) + ")]]"));
  const std::string cpp = backgroundShadersCpp(background);
  EXPECT_TRUE(contains(cpp, "const ShaderProgram& backgroundProgram()"));
  EXPECT_TRUE(contains(cpp, "kBackgroundFragmentSpirv"));
}
