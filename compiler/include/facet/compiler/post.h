// The post domain: the full-screen pass after the forward pass (tone mapping, sRGB encoding),
// compiled through the same pipeline as materials (glslang -> spirv-val -> spirv-opt ->
// SPIRV-Cross), in every form the runtime's two render paths need:
//   sampled: the separate path, reading the stored HDR texture;
//   fetch:   the merged path, reading the pixel's own HDR value in the same render pass
//            (Vulkan subpassInput; GLES GL_EXT_shader_framebuffer_fetch `inout`; MSL [[color(0)]]).
// Post variants are keyed by the effects enabled; an effect that is off is not in the shader.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/package/package.h"

namespace facet::compiler {

enum class ToneCurve {
  None,     // HDR clamped to [0, 1]
  Aces,     // chunks/tonemap_aces.glsl: filmic (Narkowicz's ACES fit)
  Neutral,  // chunks/tonemap_neutral.glsl: Khronos PBR Neutral, hue-preserving below its knee
};
const char* toString(ToneCurve curve);
std::optional<ToneCurve> toneCurveFromString(std::string_view name);

struct PostEffects {
  ToneCurve toneCurve = ToneCurve::Aces;
  bool dither = false;  // chunks/dither.glsl: triangular noise of ±1 step before 8-bit quantisation
  // chunks/color_grading.glsl: the encoded colour through a 3D LUT (shader_abi.h kPostColorLutBinding)
  bool colorGrading = false;
  // chunks/vignette.glsl: darker corners, from the PostUniforms block (shader_abi.h kPostBlock)
  bool vignette = false;
  // chunks/bloom.glsl: the bloom chain's finest level (PostShaders' bloom passes make it, the
  // runtime's abi::kPostBloomBinding) composited into HDR before the tone curve, from the block
  bool bloom = false;
};

// A stable name of the effects, e.g. "aces", "neutral+dither" or "aces+grading+vignette+dither":
// the post variant key (tone curve, then grading, vignette, dither when on).
std::string postVariantKey(const PostEffects& effects);

struct PostStage {
  std::vector<uint32_t> spirv;  // Vulkan flavour, optimized, validated
  std::string glslEs;           // "#version 300 es" text
  std::string msl;              // Metal (iOS, MSL 2.0)
};

struct PostShaders {
  PostEffects effects;        // postVariantKey(effects) names the variant
  PostStage vertex;           // full-screen triangle, shared by both forms
  PostStage sampledFragment;  // separate path
  // Merged path. glslang 12 rejects the GL_EXT_shader_framebuffer_fetch #extension, so the GLES
  // text is assembled but not checked here: tests compile it with Mesa (OSMesa / EGL).
  PostStage fetchFragment;
  // Render scale < 1 (separate path): samples an HDR image smaller than the output bilinearly.
  PostStage upscaledFragment;
  // Merged path under MSAA with multisampled attachments (Vulkan's portable form): reads each
  // sample of the multisampled HDR (subpassInputMS, abi::kPostSampleCountConstantId samples),
  // tone maps it and averages in display light. glslEs is the same loop over a sampler2DMS in
  // GLSL ES 3.10 (for Mesa's cycle counts; the GL backend resolves first); no Metal. Empty for
  // bloom variants: bloom runs the separate path.
  PostStage samplesFragment;
};

// Returns false with *error set when a backend rejects the assembled code (a compiler defect).
bool buildPostShaders(const PostEffects& effects, PostShaders* out, std::string* error);

// The FXAA pass's fragment stage (chunks/fxaa.glsl, templates/post_fxaa.frag.glsl), one form for
// both render paths (it samples the stored tone-mapped image); its vertex stage is any post
// variant's full-screen triangle.
bool buildFxaaShader(PostStage* fragment, std::string* error);

// The bloom chain's passes (chunks/bloom.glsl): their vertex stage (the full-screen triangle with
// a texture coordinate), the 13-tap downsample, the same with the threshold (the first level when
// a threshold is set; it reads the PostUniforms block) and the tent upsample. Each samples
// abi::kBloomSourceName and writes one colour.
struct BloomStages {
  PostStage vertex;
  PostStage downsample;
  PostStage downsampleThreshold;
  PostStage upsample;
};
bool buildBloomShaders(BloomStages* out, std::string* error);

// The environment drawn as the background (templates/post_background.*.glsl, runtime/background.h):
// not a pass of its own but a draw of the forward pass (a full-screen triangle at the far plane,
// its parameters in the MaterialParams slot as abi::BackgroundParams, the frame's
// facet_environment), so it runs under the forward pass's MSAA, render scale and path.
struct BackgroundStages {
  PostStage vertex;
  PostStage fragment;
};
bool buildBackgroundShaders(BackgroundStages* out, std::string* error);
// Where a Metal app binds its resources: ObjectUniforms and the parameters, the environment.
std::vector<package::MslBinding> backgroundMslBindings();
// C++ source defining facet::runtime::backgroundProgram() (render_backend.h), appended to
// postShadersCpp's in the runtime's generated source.
std::string backgroundShadersCpp(const BackgroundStages& stages);

// Every combination of effects: what the runtime embeds.
std::vector<PostEffects> everyPostEffects();

// Where a Metal app binds the post fragment stage's resources (HDR texture when sampled, the
// grading LUT, the PostUniforms block): pinned from shader_abi.h like a material's slots.
// upscaled: the upscaled form, which reads the block for the output's size.
std::vector<package::MslBinding> postMslBindings(const PostEffects& effects, bool upscaled = false);

// C++ source defining facet::runtime::postVariants() (runtime/include/facet/runtime/render_backend.h)
// with these variants' SPIR-V words and GLSL ES texts, fxaaShader() with the FXAA pass's and
// bloomShaders() with the bloom chain's: how the runtime gets its post passes without linking the
// compiler.
std::string postShadersCpp(const std::vector<PostShaders>& variants, const PostStage& fxaa, const BloomStages& bloom);

}  // namespace facet::compiler
