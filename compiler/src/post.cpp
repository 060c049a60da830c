#include "facet/compiler/post.h"

#include <cstdio>
#include <span>

#include "facet/abi/shader_abi.h"
#include "facet/compiler/assemble.h"
#include "facet/compiler/glsl_library.h"
#include "facet/compiler/glslang_backend.h"
#include "facet/compiler/msl_backend.h"
#include "facet/compiler/spirv_tools_backend.h"

namespace facet::compiler {
namespace {

// Upscaled: the separate path's read of an HDR image rendered at a smaller size (render scale),
// filtered bilinearly at the output pixel's centre. SubpassSamples: the merged path under MSAA
// reading every sample of the multisampled HDR (subpassInputMS); SampledSamples, its GLSL ES 3.10
// text, the same loop over a sampler2DMS (GLSL ES 3.00 has no per-sample reads).
enum class PostRead { Sampled, SubpassInput, FramebufferFetch, Upscaled, SubpassSamples, SampledSamples };

bool readsSamples(PostRead read) { return read == PostRead::SubpassSamples || read == PostRead::SampledSamples; }

// The post fragment stage's interface, printed from shader_abi.h's attachment constants: where
// the HDR colour of the forward pass is read from, and where the LDR result goes.
std::string postInterface(Flavour flavour, PostRead read) {
  const std::string hdr(abi::kPostHdrName);
  const std::string setBinding =
      "set = " + std::to_string(abi::kPostHdrSet) + ", binding = " + std::to_string(abi::kPostHdrBinding);
  auto ldr = [](uint32_t location) {
    return "layout(location = " + std::to_string(location) + ") out vec4 fragColor;\n";
  };
  switch (read) {
    case PostRead::SubpassInput:
      return "layout(input_attachment_index = " + std::to_string(abi::kPostHdrInputAttachmentIndex) + ", " +
             setBinding + ") uniform mediump subpassInput " + hdr + ";\n" + ldr(abi::kPostMergedLdrLocation);
    case PostRead::SubpassSamples:
      return "layout(constant_id = " + std::to_string(abi::kPostSampleCountConstantId) +
             ") const int facet_postSamples = 4;\nlayout(input_attachment_index = " +
             std::to_string(abi::kPostHdrInputAttachmentIndex) + ", " + setBinding +
             ") uniform mediump subpassInputMS " + hdr + ";\n" + ldr(abi::kPostMergedLdrLocation);
    case PostRead::SampledSamples:
      return "const int facet_postSamples = 4;\nuniform mediump sampler2DMS " + hdr + ";\n" +
             ldr(abi::kPostMergedLdrLocation);
    case PostRead::FramebufferFetch:
      return "layout(location = " + std::to_string(abi::kPostHdrColorLocation) + ") inout mediump vec4 " + hdr + ";\n" +
             ldr(abi::kPostMergedLdrLocation);
    case PostRead::Sampled:
    case PostRead::Upscaled:
      return (flavour == Flavour::Vulkan ? "layout(" + setBinding + ") " : std::string()) +
             "uniform mediump sampler2D " + hdr + ";\n" + ldr(abi::kPostSeparateLdrLocation);
  }
  return "";
}

// The effects' own inputs, also from shader_abi.h: the grading LUT (sampler3D has no default
// precision in GLSL ES, so it is given) and the PostUniforms block.
std::string effectInputs(Flavour flavour, const PostEffects& effects, PostRead read) {
  std::string text;
  if (effects.colorGrading) {
    const abi::SamplerDesc& lut = abi::kPostColorLutSampler;
    text += "#define FACET_COLOR_LUT_SIZE " + std::to_string(abi::kColorLutSize) + "\n";
    if (flavour == Flavour::Vulkan)
      text += "layout(set = " + std::to_string(lut.set) + ", binding = " + std::to_string(lut.binding) + ") ";
    text += "uniform mediump sampler3D " + std::string(lut.name) + ";\n";
  }
  if (effects.bloom) {
    if (flavour == Flavour::Vulkan)
      text += "layout(set = " + std::to_string(abi::kPostHdrSet) +
              ", binding = " + std::to_string(abi::kPostBloomBinding) + ") ";
    text += "uniform mediump sampler2D " + std::string(abi::kPostBloomName) + ";\n";
  }
  // The upscaled read takes the output's pixel size from the block's viewport, bloom its parameters
  // and the output's size.
  if (effects.vignette || effects.bloom || read == PostRead::Upscaled)
    text += uniformBlockDeclaration(flavour, abi::kPostBlock);
  return text;
}

bool appendLibraryFiles(const std::vector<std::string>& files, std::string* text, std::string* error) {
  const auto& library = glslLibrary();
  for (const std::string& name : files) {
    auto found = library.find(name);
    if (found == library.end()) {
      *error = "internal error: post domain needs '" + name + "', which the compiler does not embed";
      return false;
    }
    *text += found->second;
  }
  return true;
}

// Prologue + the chunks the effects need + the template, as materials are assembled: the
// Vulkan flavour is ES 3.10 with FACET_VULKAN, the GLES flavour ES 3.00.
bool assemblePost(const PostEffects& effects, Flavour flavour, PostRead read, const char* templateName,
                  std::string* out, std::string* error) {
  std::string text = flavour == Flavour::Vulkan ? "#version 310 es\n#define FACET_VULKAN 1\n"
                     : readsSamples(read)       ? "#version 310 es\n"
                                                : "#version 300 es\n";
  if (read == PostRead::FramebufferFetch) text += "#extension GL_EXT_shader_framebuffer_fetch : require\n";
  if (read == PostRead::SubpassSamples) text += "#define FACET_POST_SUBPASS_SAMPLES 1\n";
  if (read == PostRead::SampledSamples) text += "#define FACET_POST_SAMPLED_SAMPLES 1\n";
  if (read == PostRead::SubpassInput) text += "#define FACET_POST_SUBPASS_INPUT 1\n";
  if (read == PostRead::FramebufferFetch) text += "#define FACET_POST_FRAMEBUFFER_FETCH 1\n";
  if (read == PostRead::Upscaled) text += "#define FACET_POST_UPSCALE 1\n";
  if (effects.toneCurve == ToneCurve::Aces) text += "#define FACET_POST_ACES 1\n";
  if (effects.toneCurve == ToneCurve::Neutral) text += "#define FACET_POST_NEUTRAL 1\n";
  if (effects.dither) text += "#define FACET_POST_DITHER 1\n";
  if (effects.colorGrading) text += "#define FACET_POST_COLOR_GRADING 1\n";
  if (effects.vignette) text += "#define FACET_POST_VIGNETTE 1\n";
  if (effects.bloom) text += "#define FACET_POST_BLOOM 1\n";
  text += "precision mediump float;\nprecision highp int;\n";
  std::vector<std::string> files;
  if (std::string(templateName).find(".frag.") != std::string::npos) {
    text += postInterface(flavour, read) + effectInputs(flavour, effects, read);
    if (effects.bloom) files.push_back("bloom.glsl");
    if (effects.toneCurve == ToneCurve::Aces) files.push_back("tonemap_aces.glsl");
    if (effects.toneCurve == ToneCurve::Neutral) files.push_back("tonemap_neutral.glsl");
    files.push_back("srgb.glsl");
    if (effects.colorGrading) files.push_back("color_grading.glsl");
    if (effects.vignette) files.push_back("vignette.glsl");
    if (effects.dither) files.push_back("dither.glsl");
  }
  files.push_back(templateName);
  if (!appendLibraryFiles(files, &text, error)) return false;
  *out = std::move(text);
  return true;
}

// The FXAA pass: the tone-mapped image as a sampler at the post pass's HDR set and binding (the
// two passes never bind at once), the anti-aliased colour at location 0.
bool assembleFxaa(Flavour flavour, const char* templateName, std::string* out, std::string* error) {
  std::string text = flavour == Flavour::Vulkan ? "#version 310 es\n#define FACET_VULKAN 1\n" : "#version 300 es\n";
  text += "precision mediump float;\nprecision highp int;\n";
  std::vector<std::string> files;
  if (std::string(templateName).find(".frag.") != std::string::npos) {
    if (flavour == Flavour::Vulkan)
      text += "layout(set = " + std::to_string(abi::kPostHdrSet) +
              ", binding = " + std::to_string(abi::kPostHdrBinding) + ") ";
    text += "uniform mediump sampler2D " + std::string(abi::kFxaaInputName) + ";\n";
    text += "layout(location = " + std::to_string(abi::kPostSeparateLdrLocation) + ") out vec4 fragColor;\n";
    files.push_back("fxaa.glsl");
  }
  files.push_back(templateName);
  if (!appendLibraryFiles(files, &text, error)) return false;
  *out = std::move(text);
  return true;
}

// A bloom pass: the source image as a sampler at the post pass's HDR set and binding (the passes
// never bind at once), the PostUniforms block for the threshold form, one colour out.
bool assembleBloom(Flavour flavour, bool threshold, const char* templateName, std::string* out, std::string* error) {
  std::string text = flavour == Flavour::Vulkan ? "#version 310 es\n#define FACET_VULKAN 1\n" : "#version 300 es\n";
  if (threshold) text += "#define FACET_BLOOM_THRESHOLD 1\n";
  text += "precision mediump float;\nprecision highp int;\n";
  std::vector<std::string> files;
  if (std::string(templateName).find(".frag.") != std::string::npos) {
    if (flavour == Flavour::Vulkan)
      text += "layout(set = " + std::to_string(abi::kPostHdrSet) +
              ", binding = " + std::to_string(abi::kPostHdrBinding) + ") ";
    text += "uniform mediump sampler2D " + std::string(abi::kBloomSourceName) + ";\n";
    if (threshold) text += uniformBlockDeclaration(flavour, abi::kPostBlock);
    text += "layout(location = " + std::to_string(abi::kPostSeparateLdrLocation) + ") out vec4 fragColor;\n";
    files.push_back("bloom.glsl");
  }
  files.push_back(templateName);
  if (!appendLibraryFiles(files, &text, error)) return false;
  *out = std::move(text);
  return true;
}

// glslang's SPIR-V validated, optimized (spirv-opt -O) and validated again.
bool finishStage(std::vector<uint32_t>* words, const std::string& what, std::string* error) {
  std::string log;
  if (!validateSpirv(*words, &log) || !optimizeSpirv(words, &log) || !validateSpirv(*words, &log)) {
    *error = "post " + what + ": SPIR-V validation/optimization failed:\n" + log;
    return false;
  }
  return true;
}

// Metal from the optimized SPIR-V, mediump as `half`, as materials get it.
bool toMsl(const std::vector<uint32_t>& words, std::span<const package::MslBinding> slots, const std::string& what,
           std::string* msl, std::string* error) {
  std::vector<uint32_t> metal = words;
  std::string log;
  if (!convertRelaxedToHalf(&metal, &log)) {
    *error = "post " + what + ": spirv-opt --convert-relaxed-to-half failed:\n" + log;
    return false;
  }
  return spirvToMsl(metal, slots, msl, error);
}

// Compiles one fragment form with the vertex stage (glslang links both), checks GLSL ES where
// glslang can, and fills the fragment's targets (and the vertex's, when asked).
bool buildForm(const PostEffects& effects, PostRead read, PostStage* fragment, PostStage* vertex, std::string* error) {
  StageSources vk, es;
  const PostRead esRead = read == PostRead::SubpassInput     ? PostRead::FramebufferFetch
                          : read == PostRead::SubpassSamples ? PostRead::SampledSamples
                                                             : read;
  if (!assemblePost(effects, Flavour::Vulkan, read, "post_fullscreen.vert.glsl", &vk.vertex, error) ||
      !assemblePost(effects, Flavour::Vulkan, read, "post_tonemap.frag.glsl", &vk.fragment, error) ||
      !assemblePost(effects, Flavour::GlslEs300, esRead, "post_fullscreen.vert.glsl", &es.vertex, error) ||
      !assemblePost(effects, Flavour::GlslEs300, esRead, "post_tonemap.frag.glsl", &es.fragment, error)) {
    return false;
  }
  const std::string what = read == PostRead::Sampled          ? "sampled form"
                           : read == PostRead::Upscaled       ? "upscaled form"
                           : read == PostRead::SubpassSamples ? "per-sample form"
                                                              : "fetch form";
  std::string log;
  if (esRead != PostRead::FramebufferFetch && !checkGlslEs300(es, &log)) {
    *error = "post " + what + ": GLSL ES 3.00 rejected:\n" + log;
    return false;
  }
  SpirvStages spirv;
  if (!compileToSpirv(vk, &spirv, &log)) {
    *error = "post " + what + ": glslang failed:\n" + log;
    return false;
  }
  // No Metal for the per-sample form: Metal's [[color(n)]] reads give a fragment only its own
  // sample, so a loop over the others has no MSL equivalent.
  if (!finishStage(&spirv.fragment, what, error) ||
      (!readsSamples(read) &&
       !toMsl(spirv.fragment, postMslBindings(effects, read == PostRead::Upscaled), what, &fragment->msl, error)))
    return false;
  fragment->spirv = std::move(spirv.fragment);
  fragment->glslEs = std::move(es.fragment);
  if (vertex) {
    if (!finishStage(&spirv.vertex, "vertex stage", error) ||
        !toMsl(spirv.vertex, {}, "vertex stage", &vertex->msl, error)) {
      return false;
    }
    vertex->spirv = std::move(spirv.vertex);
    vertex->glslEs = std::move(es.vertex);
  }
  return true;
}

void appendWords(std::string* cpp, const char* name, const std::vector<uint32_t>& words) {
  *cpp += "const uint32_t ";
  *cpp += name;
  *cpp += "[] = {";
  char word[16];
  for (size_t i = 0; i < words.size(); ++i) {
    if (i % 8 == 0) *cpp += "\n ";
    std::snprintf(word, sizeof word, " 0x%08x,", words[i]);
    *cpp += word;
  }
  *cpp += "\n};\n";
}

void appendText(std::string* cpp, const char* name, const std::string& text) {
  *cpp += "const char ";
  *cpp += name;
  *cpp += "[] = R\"facet_glsl(" + text + ")facet_glsl\";\n";
}

}  // namespace

const char* toString(ToneCurve curve) {
  switch (curve) {
    case ToneCurve::None: return "none";
    case ToneCurve::Aces: return "aces";
    case ToneCurve::Neutral: return "neutral";
  }
  return "?";
}

std::optional<ToneCurve> toneCurveFromString(std::string_view name) {
  for (ToneCurve c : {ToneCurve::None, ToneCurve::Aces, ToneCurve::Neutral})
    if (name == toString(c)) return c;
  return std::nullopt;
}

std::string postVariantKey(const PostEffects& effects) {
  return std::string(toString(effects.toneCurve)) + (effects.colorGrading ? "+grading" : "") +
         (effects.vignette ? "+vignette" : "") + (effects.dither ? "+dither" : "") + (effects.bloom ? "+bloom" : "");
}

std::vector<package::MslBinding> postMslBindings(const PostEffects& effects, bool upscaled) {
  // The sampled form's HDR texture; the fetch form reads [[color(0)]] instead and ignores it.
  std::vector<package::MslBinding> slots{{std::string(abi::kPostHdrName), package::MslResource::Texture,
                                          abi::kPostHdrSet, abi::kPostHdrBinding,
                                          abi::mslTextureIndex(abi::kPostHdrBinding)}};
  if (effects.colorGrading) {
    const abi::SamplerDesc& lut = abi::kPostColorLutSampler;
    slots.push_back({std::string(lut.name), package::MslResource::Texture, lut.set, lut.binding,
                     abi::mslTextureIndex(lut.binding)});
  }
  if (effects.bloom)
    slots.push_back({std::string(abi::kPostBloomName), package::MslResource::Texture, abi::kPostHdrSet,
                     abi::kPostBloomBinding, abi::mslTextureIndex(abi::kPostBloomBinding)});
  if (effects.vignette || effects.bloom || upscaled) {
    const abi::BlockDesc& block = abi::kPostBlock;
    slots.push_back(
        {std::string(block.name), package::MslResource::Buffer, block.set, block.binding, abi::mslBufferIndex(block)});
  }
  return slots;
}

bool buildPostShaders(const PostEffects& effects, PostShaders* out, std::string* error) {
  PostShaders shaders;
  shaders.effects = effects;
  if (!buildForm(effects, PostRead::Sampled, &shaders.sampledFragment, &shaders.vertex, error) ||
      !buildForm(effects, PostRead::SubpassInput, &shaders.fetchFragment, nullptr, error) ||
      !buildForm(effects, PostRead::Upscaled, &shaders.upscaledFragment, nullptr, error) ||
      (!effects.bloom && !buildForm(effects, PostRead::SubpassSamples, &shaders.samplesFragment, nullptr, error))) {
    return false;
  }
  *out = std::move(shaders);
  return true;
}

namespace {

// A pass of one sampled input (FXAA, the bloom chain, the background) from its assembled sources:
// GLSL ES checked, SPIR-V compiled, validated and optimised, Metal with `slots`; the vertex stage's
// targets too when `vertex` is not null, its Metal with `vertexSlots`.
bool buildSampledPass(const StageSources& vk, const StageSources& es, const std::vector<package::MslBinding>& slots,
                      const std::string& what, PostStage* fragment, PostStage* vertex, std::string* error,
                      const std::vector<package::MslBinding>& vertexSlots = {}) {
  std::string log;
  if (!checkGlslEs300(es, &log)) {
    *error = "post " + what + ": GLSL ES 3.00 rejected:\n" + log;
    return false;
  }
  SpirvStages spirv;
  if (!compileToSpirv(vk, &spirv, &log)) {
    *error = "post " + what + ": glslang failed:\n" + log;
    return false;
  }
  if (!finishStage(&spirv.fragment, what, error) || !toMsl(spirv.fragment, slots, what, &fragment->msl, error))
    return false;
  fragment->spirv = std::move(spirv.fragment);
  fragment->glslEs = es.fragment;
  if (!vertex) return true;
  if (!finishStage(&spirv.vertex, what + " vertex stage", error) ||
      !toMsl(spirv.vertex, vertexSlots, what + " vertex stage", &vertex->msl, error))
    return false;
  vertex->spirv = std::move(spirv.vertex);
  vertex->glslEs = es.vertex;
  return true;
}

package::MslBinding sourceTexture(std::string_view name) {
  return {std::string(name), package::MslResource::Texture, abi::kPostHdrSet, abi::kPostHdrBinding,
          abi::mslTextureIndex(abi::kPostHdrBinding)};
}

}  // namespace

bool buildFxaaShader(PostStage* fragment, std::string* error) {
  StageSources vk, es;
  if (!assembleFxaa(Flavour::Vulkan, "post_fullscreen.vert.glsl", &vk.vertex, error) ||
      !assembleFxaa(Flavour::Vulkan, "post_fxaa.frag.glsl", &vk.fragment, error) ||
      !assembleFxaa(Flavour::GlslEs300, "post_fullscreen.vert.glsl", &es.vertex, error) ||
      !assembleFxaa(Flavour::GlslEs300, "post_fxaa.frag.glsl", &es.fragment, error)) {
    return false;
  }
  return buildSampledPass(vk, es, {sourceTexture(abi::kFxaaInputName)}, "fxaa", fragment, nullptr, error);
}

bool buildBloomShaders(BloomStages* out, std::string* error) {
  struct Form {
    const char* templateName;
    bool threshold;
    PostStage* stage;
    const char* what;
  };
  BloomStages stages;
  const Form forms[] = {{"post_bloom_down.frag.glsl", false, &stages.downsample, "bloom downsample"},
                        {"post_bloom_down.frag.glsl", true, &stages.downsampleThreshold, "bloom threshold"},
                        {"post_bloom_up.frag.glsl", false, &stages.upsample, "bloom upsample"}};
  for (const Form& form : forms) {
    StageSources vk, es;
    if (!assembleBloom(Flavour::Vulkan, form.threshold, "post_bloom.vert.glsl", &vk.vertex, error) ||
        !assembleBloom(Flavour::Vulkan, form.threshold, form.templateName, &vk.fragment, error) ||
        !assembleBloom(Flavour::GlslEs300, form.threshold, "post_bloom.vert.glsl", &es.vertex, error) ||
        !assembleBloom(Flavour::GlslEs300, form.threshold, form.templateName, &es.fragment, error)) {
      return false;
    }
    std::vector<package::MslBinding> slots{sourceTexture(abi::kBloomSourceName)};
    if (form.threshold) {
      const abi::BlockDesc& block = abi::kPostBlock;
      slots.push_back({std::string(block.name), package::MslResource::Buffer, block.set, block.binding,
                       abi::mslBufferIndex(block)});
    }
    // The vertex stage is the same for every form: kept from the first.
    PostStage* vertex = stages.vertex.spirv.empty() ? &stages.vertex : nullptr;
    if (!buildSampledPass(vk, es, slots, form.what, form.stage, vertex, error)) return false;
  }
  *out = std::move(stages);
  return true;
}

namespace {

// The background's stages: the mesh's position attribute and ObjectUniforms (its decoding) in the
// vertex stage, the parameters in both (the same text, as GLSL ES requires of a block in two
// stages), the environment and the forward pass's colour in the fragment stage.
bool assembleBackground(Flavour flavour, const char* templateName, std::string* out, std::string* error) {
  std::string text = flavour == Flavour::Vulkan ? "#version 310 es\n#define FACET_VULKAN 1\n" : "#version 300 es\n";
  text += "precision mediump float;\nprecision highp int;\n";
  text += uniformBlockDeclaration(flavour, abi::kBackgroundBlock);
  if (std::string(templateName).find(".vert.") != std::string::npos) {
    text += "layout(location = " + std::to_string(abi::kAttribPosition) + ") in highp vec3 a_position;\n";
    text += uniformBlockDeclaration(flavour, abi::kObjectBlock);
  } else {
    const abi::SamplerDesc& environment = abi::kEnvironmentSampler;
    if (flavour == Flavour::Vulkan)
      text += "layout(set = " + std::to_string(environment.set) + ", binding = " + std::to_string(environment.binding) +
              ") ";
    text += "uniform mediump samplerCube " + std::string(environment.name) + ";\n";
    text += "layout(location = " + std::to_string(abi::kForwardColorLocation) + ") out vec4 fragColor;\n";
  }
  if (!appendLibraryFiles({templateName}, &text, error)) return false;
  *out = std::move(text);
  return true;
}

package::MslBinding mslBlock(const abi::BlockDesc& block) {
  return {std::string(block.name), package::MslResource::Buffer, block.set, block.binding, abi::mslBufferIndex(block)};
}

}  // namespace

std::vector<package::MslBinding> backgroundMslBindings() {
  const abi::SamplerDesc& environment = abi::kEnvironmentSampler;
  return {mslBlock(abi::kObjectBlock),
          mslBlock(abi::kBackgroundBlock),
          {std::string(environment.name), package::MslResource::Texture, environment.set, environment.binding,
           abi::mslTextureIndex(environment.binding)}};
}

bool buildBackgroundShaders(BackgroundStages* out, std::string* error) {
  StageSources vk, es;
  if (!assembleBackground(Flavour::Vulkan, "post_background.vert.glsl", &vk.vertex, error) ||
      !assembleBackground(Flavour::Vulkan, "post_background.frag.glsl", &vk.fragment, error) ||
      !assembleBackground(Flavour::GlslEs300, "post_background.vert.glsl", &es.vertex, error) ||
      !assembleBackground(Flavour::GlslEs300, "post_background.frag.glsl", &es.fragment, error)) {
    return false;
  }
  const std::vector<package::MslBinding> slots = backgroundMslBindings();
  BackgroundStages stages;
  if (!buildSampledPass(vk, es, slots, "background", &stages.fragment, &stages.vertex, error, slots)) return false;
  *out = std::move(stages);
  return true;
}

std::string backgroundShadersCpp(const BackgroundStages& stages) {
  std::string cpp = "// The environment background (compiler/src/post.cpp: buildBackgroundShaders)\nnamespace {\n";
  appendWords(&cpp, "kBackgroundVertexSpirv", stages.vertex.spirv);
  appendWords(&cpp, "kBackgroundFragmentSpirv", stages.fragment.spirv);
  appendText(&cpp, "kBackgroundVertexEs", stages.vertex.glslEs);
  appendText(&cpp, "kBackgroundFragmentEs", stages.fragment.glslEs);
  cpp +=
      "}  // namespace\n\n"
      "namespace facet::runtime {\n"
      "const ShaderProgram& backgroundProgram() {\n"
      "  static const ShaderProgram program{{std::begin(kBackgroundVertexSpirv), std::end(kBackgroundVertexSpirv)},\n"
      "                                     {std::begin(kBackgroundFragmentSpirv), "
      "std::end(kBackgroundFragmentSpirv)},\n"
      "                                     kBackgroundVertexEs, kBackgroundFragmentEs, std::nullopt};\n"
      "  return program;\n"
      "}\n"
      "}  // namespace facet::runtime\n";
  return cpp;
}

std::vector<PostEffects> everyPostEffects() {
  std::vector<PostEffects> all;
  for (bool bloom : {false, true})
    for (ToneCurve curve : {ToneCurve::Aces, ToneCurve::Neutral, ToneCurve::None})
      for (bool grading : {false, true})
        for (bool vignette : {false, true})
          for (bool dither : {false, true}) all.push_back({curve, dither, grading, vignette, bloom});
  return all;
}

std::string postShadersCpp(const std::vector<PostShaders>& variants, const PostStage& fxaa, const BloomStages& bloom) {
  std::string cpp =
      "// Generated by `matc post` (compiler/src/post.cpp) from templates/post_* and chunks/. Do not edit.\n"
      "#include <cstdint>\n#include <iterator>\n#include <string>\n#include <vector>\n\n"
      "#include \"facet/runtime/render_backend.h\"\n\nnamespace {\n";
  for (size_t i = 0; i < variants.size(); ++i) {
    const PostShaders& shaders = variants[i];
    const std::string n = std::to_string(i);
    cpp += "// Post variant " + n + ": " + postVariantKey(shaders.effects) + "\n";
    appendWords(&cpp, ("kVertexSpirv" + n).c_str(), shaders.vertex.spirv);
    appendWords(&cpp, ("kSampledSpirv" + n).c_str(), shaders.sampledFragment.spirv);
    appendWords(&cpp, ("kFetchSpirv" + n).c_str(), shaders.fetchFragment.spirv);
    appendWords(&cpp, ("kUpscaledSpirv" + n).c_str(), shaders.upscaledFragment.spirv);
    // Bloom variants have no per-sample form (bloom runs the separate path), and C++ has no
    // empty array.
    if (!shaders.samplesFragment.spirv.empty())
      appendWords(&cpp, ("kSamplesSpirv" + n).c_str(), shaders.samplesFragment.spirv);
    appendText(&cpp, ("kVertexEs" + n).c_str(), shaders.vertex.glslEs);
    appendText(&cpp, ("kSampledEs" + n).c_str(), shaders.sampledFragment.glslEs);
    appendText(&cpp, ("kFetchEs" + n).c_str(), shaders.fetchFragment.glslEs);
    appendText(&cpp, ("kUpscaledEs" + n).c_str(), shaders.upscaledFragment.glslEs);
  }
  cpp += "// The FXAA pass\n";
  appendWords(&cpp, "kFxaaSpirv", fxaa.spirv);
  appendText(&cpp, "kFxaaEs", fxaa.glslEs);
  cpp += "// The bloom chain\n";
  appendWords(&cpp, "kBloomVertexSpirv", bloom.vertex.spirv);
  appendWords(&cpp, "kBloomDownSpirv", bloom.downsample.spirv);
  appendWords(&cpp, "kBloomThresholdSpirv", bloom.downsampleThreshold.spirv);
  appendWords(&cpp, "kBloomUpSpirv", bloom.upsample.spirv);
  appendText(&cpp, "kBloomVertexEs", bloom.vertex.glslEs);
  appendText(&cpp, "kBloomDownEs", bloom.downsample.glslEs);
  appendText(&cpp, "kBloomThresholdEs", bloom.downsampleThreshold.glslEs);
  appendText(&cpp, "kBloomUpEs", bloom.upsample.glslEs);
  cpp +=
      "template <size_t N>\nstd::vector<uint32_t> words(const uint32_t (&w)[N]) { return {std::begin(w), std::end(w)}; "
      "}\n"
      "}  // namespace\n\n"
      "namespace facet::runtime {\n"
      "const std::vector<PostShaders>& postVariants() {\n";
  for (size_t i = 0; i < variants.size(); ++i) {
    const std::string n = std::to_string(i);
    cpp += "  static const std::vector<uint32_t> vs" + n + " = words(kVertexSpirv" + n + "), fs" + n +
           " = words(kSampledSpirv" + n + "), fsFetch" + n + " = words(kFetchSpirv" + n + "), fsUpscaled" + n +
           " = words(kUpscaledSpirv" + n + "), fsSamples" + n + " = " +
           (variants[i].samplesFragment.spirv.empty() ? "std::vector<uint32_t>()" : "words(kSamplesSpirv" + n + ")") +
           ";\n";
    cpp += "  static const std::string vsText" + n + "(kVertexEs" + n + "), fsText" + n + "(kSampledEs" + n +
           "), fsFetchText" + n + "(kFetchEs" + n + "), fsUpscaledText" + n + "(kUpscaledEs" + n + ");\n";
  }
  cpp += "  static const std::vector<PostShaders> variants{\n";
  for (size_t i = 0; i < variants.size(); ++i) {
    const std::string n = std::to_string(i);
    const PostEffects& e = variants[i].effects;
    auto flag = [](bool on) { return on ? ", true" : ", false"; };
    cpp += std::string("      {{\"") + toString(e.toneCurve) + "\"" + flag(e.dither) + flag(e.colorGrading) +
           flag(e.vignette) + flag(e.bloom) + "}, vs" + n + ", fs" + n + ", fsFetch" + n + ", vsText" + n + ", fsText" +
           n + ", fsFetchText" + n + ", fsUpscaled" + n + ", fsUpscaledText" + n + ", fsSamples" + n + "},\n";
  }
  cpp +=
      "  };\n"
      "  return variants;\n"
      "}\n"
      "const FxaaShader& fxaaShader() {\n"
      "  static const std::vector<uint32_t> spirv = words(kFxaaSpirv);\n"
      "  static const std::string text(kFxaaEs);\n"
      "  static const FxaaShader shader{spirv, text};\n"
      "  return shader;\n"
      "}\n"
      "const BloomShaders& bloomShaders() {\n"
      "  static const BloomShaders shaders{words(kBloomVertexSpirv), words(kBloomDownSpirv),\n"
      "                                    words(kBloomThresholdSpirv), words(kBloomUpSpirv),\n"
      "                                    kBloomVertexEs, kBloomDownEs, kBloomThresholdEs, kBloomUpEs};\n"
      "  return shaders;\n"
      "}\n"
      "}  // namespace facet::runtime\n";
  return cpp;
}

}  // namespace facet::compiler
