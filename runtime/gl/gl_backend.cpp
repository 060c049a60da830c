// RenderBackend on OpenGL ES: forward pass into RGBA16F + depth, post pass into RGBA8, read back
// (render()) or drawn into the app's framebuffer (renderToFramebuffer()).
//
// Runs the "#version 300 es" shaders on the context it is given (gl_backend.h): the app's, or in
// tests a real OpenGL ES 3.2 context (EGL surfaceless) or Mesa's OSMesa core context
// (ARB_ES3_compatibility), so the GLES flavour of every material is exercised as a phone would
// receive it. Render paths (render_path.h): merged
// (one framebuffer, the post pass reads HDR by GL_EXT_shader_framebuffer_fetch, then HDR and
// depth are invalidated) or separate (post samples the HDR texture).
#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>
#include <optional>
#include <string_view>
#include <unordered_map>

#include "facet/runtime/frame_eviction.h"
#include "facet/runtime/gl_backend.h"
#include "facet/runtime/render_backend.h"
#include "gl_app_target.h"
#include "gl_bloom.h"
#include "gl_context.h"
#include "gl_mesh.h"
#include "gl_post_inputs.h"
#include "gl_program.h"
#include "gl_reflection.h"
#include "gl_row_order.h"
#include "gl_shadow_atlas.h"
#include "gl_targets.h"
#include "gl_textures.h"
#include "gl_uniform_blocks.h"

namespace facet::runtime {
namespace {

using gl::checkGlError;

// Builds a post program; a `sampled` one (separate path, FXAA) gets its sampler `samplerName` pointed
// at unit kPostHdrBinding once, since sampler uniforms are program state.
bool buildPostProgram(const std::string& vertex, const std::string& fragment, bool sampled, gl::LinkedProgram* out,
                      std::string* error, std::string_view samplerName = abi::kPostHdrName) {
  std::string buildError;
  std::optional<gl::LinkedProgram> post = gl::buildProgram(vertex, fragment, &buildError);
  if (!post) {
    *error = "post-pass shaders: " + buildError;
    return false;
  }
  *out = std::move(*post);
  if (!sampled) return true;
  const GLint hdrLocation = glGetUniformLocation(out->program.id(), std::string(samplerName).c_str());
  if (hdrLocation < 0) {
    *error = "post-pass fragment shader has no sampler uniform '" + std::string(samplerName) + "'";
    return false;
  }
  glUseProgram(out->program.id());
  glUniform1i(hdrLocation, static_cast<GLint>(abi::kPostHdrBinding));
  glUseProgram(0);
  return true;
}

// State the passes and uploads rely on that an app's context may have left otherwise (the
// backend's own contexts start at GL's defaults, the app's has the app's last pass in it): a
// scissor would clip the frame, a bound pixel-unpack buffer would make texture uploads read it.
void resetAppState() {
  for (GLenum capability : {GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_POLYGON_OFFSET_FILL, GL_RASTERIZER_DISCARD,
                            GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_COVERAGE}) {
    glDisable(capability);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  for (GLenum layout : {GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS,
                        GL_UNPACK_SKIP_IMAGES, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS}) {
    glPixelStorei(layout, 0);
  }
}

// Runs a frame's body, turning its failure message (or an exception) into *error. Nothing in a
// frame throws by design; the catch keeps the never-throws contract if allocation fails.
template <typename Body>
bool guarded(const Body& body, std::string& message, std::string* error) {
  bool ok = false;
  try {
    ok = body();
  } catch (const std::exception& e) {
    message = e.what();
  }
  if (!ok && error) *error = "GL backend: " + message;
  return ok;
}

// What gl_backend.h promises the app finds bound after a frame.
void leaveState(GLuint framebuffer, uint32_t width, uint32_t height) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, static_cast<GLsizei>(width), static_cast<GLsizei>(height));
  glUseProgram(0);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDepthMask(GL_TRUE);
}

class GlBackend final : public GlRenderer {
 public:
  static std::unique_ptr<GlBackend> create(std::unique_ptr<GlContext> host, const GlOptions& options,
                                           std::string* error);
  ~GlBackend() override;

  const char* name() const override { return "gl"; }
  PostPath postPath() const override { return path_; }
  bool readsBackHdr() const override { return readBackHdr_; }
  HdrFormat hdrFormat() const override { return hdrFormat_; }
  uint32_t msaaSamples() const override { return uint32_t(samples_); }
  bool fxaa() const override { return fxaa_; }
  double renderScale() const override { return renderScale_; }
  int bloomLevels() const override { return bloomOn_ ? bloom_.levels : 0; }
  std::string msaaMethod() const override {
    if (samples_ == 1) return "off";
    return renderToTexture_ ? "GL_EXT_multisampled_render_to_texture (samples kept by the driver)"
                            : "multisampled renderbuffers resolved by glBlitFramebuffer, then invalidated";
  }
  bool render(const FrameDesc& frame, FrameResult* result, std::string* error) override;
  bool renderToFramebuffer(const FrameDesc& frame, const GlAppTarget& target, std::string* error) override;
  const std::vector<std::string>& validationErrors() const override { return context_->debugErrors(); }
  ResourceCounts resources() const override {
    ResourceCounts counts{meshes_.residentCount(), meshes_.uploadCount(), materialBlocks_.residentCount(),
                          materialBlocks_.uploadCount()};
    counts.compressedTextureUploads = textures_.compressedUploads();
    counts.decodedTextureUploads = textures_.decodedUploads();
    counts.programs = programs_.size();
    counts.programBuilds = programBuilds_;
    return counts;
  }

 private:
  struct CachedProgram {
    std::string vertexSource;  // compared on lookup: a freed ShaderProgram's address may be reused
    std::string fragmentSource;
    gl::LinkedProgram linked;
    gl::SamplerUnits samplerUnits;  // sampler uniforms already pointed at their units
    uint64_t lastUsedFrame = 0;     // deleted after kEvictAfterFrames frames unused (frame_eviction.h)
  };

  GlBackend() = default;
  bool initialise(std::unique_ptr<GlContext> host, const GlOptions& options, std::string* error);
  // The frame's shadow pass checked (none: true) before anything reads its casters; false: refused, *error says why.
  bool checkShadowPass(const FrameDesc& frame, std::string* error) const;
  // What every frame does first: the context current, the size in range, stale errors drained,
  // textures checked, targets and textures made.
  bool beginFrame(const FrameDesc& frame, std::string* error);
  bool prepareTargets(uint32_t width, uint32_t height, std::string* error);
  bool checkSampleCount(uint32_t samples, std::string* error);
  // MSAA: the multisampled colour blitted into the HDR texture, then the samples invalidated.
  void resolveSamples(uint32_t width, uint32_t height);
  // `framebuffer`: the merged one (HDR, LDR, depth) when `merged`, else the HDR one.
  // With a shadow pass, that pass first, then the forward draws, in `rows` (gl_row_order.h).
  bool forwardPass(const FrameDesc& frame, GLuint framebuffer, bool merged, gl::RowOrder rows, std::string* error);
  // The frame's instances in one upload (both passes', FrameDraws' order); each draw points the instance
  // attributes at its own.
  bool uploadInstances(const FrameDesc& frame, std::string* error);
  // The sun's shadow pass (docs/shadows.md): the atlas cleared to depth 1, then each of the
  // desc's views drawn into its rectangle, each its casters read in place from the desc.
  bool shadowPass(const FrameDesc& frame, std::string* error);
  // One view of the shadow pass: its rectangle, bias and frame block, its casters.
  bool drawShadowView(const FrameDesc& frame, const ShadowCascadeDesc& view, std::string* error);
  // A forward draw in `rows`; or, with `caster`, a shadow pass draw (no alpha to coverage: the
  // atlas has one sample; the atlas keeps GL's clip y, so `rows` is BottomUp).
  bool drawItem(const FrameDesc& frame, const DrawItem& item, gl::RowOrder rows, std::string* error,
                bool caster = false);
  // Separate path: samples the HDR texture, draws into `framebuffer` (the backend's LDR one, or the app's).
  bool postPass(const FrameDesc& frame, GLuint framebuffer, std::string* error);
  // Merged path, into the framebuffer the forward pass drew into; HDR invalidated unless `keepHdr`.
  bool mergedPostPass(const FrameDesc& frame, bool keepHdr, std::string* error);
  // A full-screen triangle of `program` sampling `input` at unit kPostHdrBinding into
  // `framebuffer`; postFrame: the post variant's inputs are bound from it (null: none).
  bool sampledPass(GLuint framebuffer, const gl::LinkedProgram& program, const gl::Texture& input,
                   const FrameDesc* postFrame, const char* what, std::string* error);
  // FXAA: samples the post pass's image (targets_.ldrColor), draws into `framebuffer`.
  bool fxaaPass(GLuint framebuffer, std::string* error) {
    return sampledPass(framebuffer, fxaaProgram_, targets_.ldrColor, nullptr, "FXAA pass", error);
  }
  CachedProgram* programFor(const ShaderProgram& program, std::string* error);

  // Declared first so it is destroyed last: every GL object below is deleted in this context.
  std::unique_ptr<gl::Context> context_;
  PostPath path_ = PostPath::Separate;
  bool readBackHdr_ = true;
  HdrFormat hdrFormat_ = HdrFormat::Rgba16Float;
  GLsizei samples_ = 1;  // MSAA samples of the forward pass
  bool fxaa_ = false;
  double renderScale_ = 1.0;       // below 1: a smaller HDR texture, upscaled by the post pass (separate path)
  gl::LinkedProgram fxaaProgram_;  // FXAA only
  // Bloom (the post variant composites it): the chain, run by postPass before the post program.
  bool bloomOn_ = false;
  BloomSettings bloom_;
  gl::BloomChain bloomChain_;
  // GL_EXT_multisampled_render_to_texture is used (GlOptions::renderToTexture and the context has it).
  bool renderToTexture_ = false;
  GLint maxTargetSize_ = 0;
  GLint maxTextureSize_ = 0;
  gl::LinkedProgram post_;            // the path's post program: framebuffer fetch when merged
  gl::LinkedProgram sampledPost_;     // merged backends: the separate path's, for frames into the
                                      // default framebuffer (which cannot lend an attachment)
  gl::PostInputs postInputs_;         // the grading LUT and the post uniforms, when the variant reads them
  gl::VertexArray emptyVertexArray_;  // core profile draws need a VAO even without attributes
  gl::Buffer frameUniforms_;
  gl::Buffer objectUniforms_;
  gl::Buffer instances_;      // every draw's InstanceTransforms of the frame, one after the other
  size_t firstInstance_ = 0;  // the next draw's first instance in instances_
  gl::Buffer materialUniforms_;
  gl::Buffer shadowUniforms_;  // ShadowUniforms, zeros without a shadow pass
  gl::ShadowAtlas shadowAtlas_;
  gl::RenderTargets targets_;
  gl::TextureCache textures_;             // kept across frames; see gl_textures.h for the reuse rule
  gl::MeshCache meshes_;                  // kept across frames, shared by every draw of a mesh (gl_mesh.h)
  gl::UniformBlockCache materialBlocks_;  // material instances' blocks (gl_uniform_blocks.h)
  // GL_TIME_ELAPSED queries of the forward and post passes; absent when the context has no
  // timer queries (GL 3.3 core has them; GLES needs GL_EXT_disjoint_timer_query).
  bool timed_ = false;
  gl::Query forwardTimer_, postTimer_;
  // Keyed by the app's ShaderProgram, which may be freed without the backend knowing: a program
  // no draw asked for in kEvictAfterFrames frames is deleted, as meshes and blocks are.
  std::unordered_map<const ShaderProgram*, CachedProgram> programs_;
  uint64_t programFrame_ = 0;  // frames begun (beginFrame)
  uint64_t programBuilds_ = 0;
};

std::unique_ptr<GlBackend> GlBackend::create(std::unique_ptr<GlContext> host, const GlOptions& options,
                                             std::string* error) {
  std::unique_ptr<GlBackend> backend(new GlBackend());
  if (!backend->initialise(std::move(host), options, error)) return nullptr;
  return backend;
}

bool GlBackend::initialise(std::unique_ptr<GlContext> host, const GlOptions& options, std::string* error) {
  context_ = gl::Context::create(std::move(host), error);
  if (!context_) return false;
  readBackHdr_ = options.readBackHdr;
  meshes_ = gl::MeshCache(options.vertexPacking);
  hdrFormat_ = options.hdrFormat;
  const bool canFetch = context_->hasExtension("GL_EXT_shader_framebuffer_fetch");
  if (options.postPath == PostPath::Merged && !canFetch) {
    if (error)
      *error = std::string("GL backend: the merged path needs GL_EXT_shader_framebuffer_fetch, which this ") +
               context_->kindName() + " context lacks";
    return false;
  }
  if (!isRenderScale(options.renderScale)) {
    if (error) *error = "GL backend: " + renderScaleError("GlOptions::renderScale", options.renderScale);
    return false;
  }
  renderScale_ = options.renderScale;
  bloomOn_ = options.post.bloom;
  bloom_ = options.bloom;
  if (bloomOn_) {
    if (const std::string why = bloomSettingsError("GlOptions::bloom", bloom_); !why.empty()) {
      if (error) *error = "GL backend: " + why;
      return false;
    }
  }
  path_ = effectivePostPath(options.postPath == PostPath::Separate || !canFetch ? PostPath::Separate : PostPath::Merged,
                            renderScale_, bloomOn_);
  if (!checkSampleCount(options.msaaSamples, error)) return false;
  renderToTexture_ = samples_ > 1 && options.renderToTexture && context_->renderToTexture().present();

  GLint maxTexture = 0;
  GLint maxRenderbuffer = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
  maxTargetSize_ = std::min(maxTexture, maxRenderbuffer);
  maxTextureSize_ = maxTexture;

  // The post program is the same for every frame: build it once, and fail creation (not the
  // first frame) if the build-time shaders do not compile here.
  const PostShaders* chosen = findPostShaders(options.post, error);
  if (!chosen) return false;
  const PostShaders& shaders = *chosen;
  const bool merged = path_ == PostPath::Merged;
  const bool upscale = renderScale_ < 1.0;
  const std::string& postFragment = merged    ? shaders.fragmentFetchGlslEs
                                    : upscale ? shaders.fragmentUpscaledGlslEs
                                              : shaders.fragmentGlslEs;
  std::string postError;
  const bool built =
      buildPostProgram(shaders.vertexGlslEs, postFragment, !merged, &post_, &postError) &&
      postInputs_.init(post_.program.id(), shaders.effects, upscale, &postError) &&
      (!merged || (buildPostProgram(shaders.vertexGlslEs, shaders.fragmentGlslEs, true, &sampledPost_, &postError) &&
                   postInputs_.pointProgram(sampledPost_.program.id(), &postError)));
  postInputs_.setBloom(bloom_);
  fxaa_ = options.fxaa;
  if (!built || (bloomOn_ && !bloomChain_.init(hdrFormat_, bloom_, &postError)) ||
      (fxaa_ && !buildPostProgram(shaders.vertexGlslEs, fxaaShader().fragmentGlslEs, true, &fxaaProgram_, &postError,
                                  abi::kFxaaInputName))) {
    if (error) *error = "GL backend: " + postError;
    return false;
  }

  // GLES timer queries (GL_EXT_disjoint_timer_query) are not used: on Mesa 22.3's llvmpipe the
  // forward pass's elapsed time comes back as a huge value (~2.5e6 ms, measured with facet-view
  // --stats) while the same code on OSMesa's desktop context gives plausible times.
  timed_ = !context_->isEs() && context_->queryResult64() != nullptr;
  if (timed_) {
    forwardTimer_ = gl::Query::generate();
    postTimer_ = gl::Query::generate();
  }
  emptyVertexArray_ = gl::VertexArray::generate();
  frameUniforms_ = gl::Buffer::generate();
  objectUniforms_ = gl::Buffer::generate();
  instances_ = gl::Buffer::generate();
  materialUniforms_ = gl::Buffer::generate();
  shadowUniforms_ = gl::Buffer::generate();
  // GL_KHR_texture_compression_astc_ldr (core in GLES 3.2) lets ASTC blocks be uploaded as they
  // are; without it (or when told to) the texture cache decodes them to RGBA8 on the CPU.
  const bool astc = context_->hasExtension("GL_KHR_texture_compression_astc_ldr");
  if (!textures_.init(astc && !options.decodeCompressedTextures, error)) {
    if (error) *error = "GL backend: " + *error;
    return false;
  }
  return checkGlError("GL backend creation", error);
}

// A count the context does not offer is an error at creation, never a GL error in a frame:
// GL_MAX_SAMPLES bounds every format, and each format's own list (glGetInternalformativ) may be
// shorter (GLES 3.0 requires multisampling for RGBA16F only with EXT_color_buffer_float).
bool GlBackend::checkSampleCount(uint32_t samples, std::string* error) {
  if (!isMsaaSampleCount(samples)) {
    if (error) *error = "GL backend: GlOptions::msaaSamples must be 1, 2 or 4, not " + std::to_string(samples);
    return false;
  }
  samples_ = static_cast<GLsizei>(samples);
  if (samples == 1) return true;
  GLint maxSamples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  const GLint offered = std::min({maxSamples, gl::maxRenderbufferSamples(gl::hdrInternalFormat(hdrFormat_)),
                                  gl::maxRenderbufferSamples(gl::kDepthInternalFormat)});
  if (GLint(samples) <= offered) return true;
  if (error)
    *error = "GL backend: MSAA " + std::to_string(samples) + "x is not offered by this " + context_->kindName() +
             " context for " + toString(hdrFormat_) + " colour with DEPTH32F (at most " + std::to_string(offered) +
             " samples)";
  return false;
}

GlBackend::~GlBackend() {
  // The members' handles delete their names in the current context, which must be ours.
  if (context_) context_->makeCurrent(nullptr);
}

bool GlBackend::checkShadowPass(const FrameDesc& frame, std::string* error) const {
  if (!frame.shadow) return true;
  // The atlas is a texture and a framebuffer's only attachment: both limits hold for it.
  *error = shadowPassError(*frame.shadow, static_cast<uint32_t>(maxTargetSize_));
  return error->empty();
}

bool GlBackend::beginFrame(const FrameDesc& frame, std::string* error) {
  if (!context_->makeCurrent(error)) return false;
  if (frame.width == 0 || frame.height == 0 || frame.width > static_cast<uint32_t>(maxTargetSize_) ||
      frame.height > static_cast<uint32_t>(maxTargetSize_)) {
    *error = "frame size " + std::to_string(frame.width) + "x" + std::to_string(frame.height) + " is outside 1.." +
             std::to_string(maxTargetSize_);
    return false;
  }
  // A failed earlier frame may have left an error flag set; it must not be blamed on this one.
  while (glGetError() != GL_NO_ERROR) {
  }
  resetAppState();
  if (!checkFrameTextures(frame, static_cast<uint32_t>(maxTextureSize_), error) ||
      !prepareTargets(frame.width, frame.height, error) || !textures_.prepare(frame, error))
    return false;
  // Every draw's program linked (and a package's checked against its interface) before anything
  // is drawn: a refused program fails the frame, not half of it.
  ++programFrame_;
  const FrameDraws draws(frame);
  for (size_t i = 0; i < draws.size(); ++i) {
    if (draws[i].program && !programFor(*draws[i].program, error)) {
      *error = "draw " + std::to_string(i) + ": " + *error;
      return false;
    }
  }
  evictUnusedEntries(programs_, programFrame_, [](auto&) {});  // GL objects delete themselves
  return true;
}

bool GlBackend::render(const FrameDesc& frame, FrameResult* result, std::string* error) {
  const auto start = std::chrono::steady_clock::now();
  std::string message;
  const auto renderFrame = [&] {
    if (!result) {
      message = "no FrameResult to fill";
      return false;
    }
    if (!checkShadowPass(frame, &message) || !beginFrame(frame, &message)) return false;
    const bool merged = path_ == PostPath::Merged;
    if (timed_) glBeginQuery(GL_TIME_ELAPSED, forwardTimer_.id());
    // Vulkan's row order (gl_row_order.h): the two APIs' images then agree to the derivative.
    const bool forwardDone = forwardPass(frame, merged ? targets_.mergedFramebuffer.id() : targets_.hdrFramebuffer.id(),
                                         merged, gl::RowOrder::TopDown, &message);
    if (timed_) glEndQuery(GL_TIME_ELAPSED);
    if (!forwardDone) return false;
    result->cpuSubmitMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    result->hdr.clear();
    // Merged: HDR is read back before the post pass, because Mesa 22.3's llvmpipe writes the
    // framebuffer-fetch `inout` colour back as zero (measured on these machines, GLES 3.2 and
    // OSMesa alike, assigned or not). Only this debug readback sees HDR after the pass; the
    // mobile path invalidates it.
    const auto readHdr = [&] {
      gl::readRgbaFloat(targets_.hdrFramebuffer.id(), GL_COLOR_ATTACHMENT0, targets_.forwardWidth,
                        targets_.forwardHeight, &result->hdr);
    };
    if (readBackHdr_ && merged) readHdr();
    if (timed_) glBeginQuery(GL_TIME_ELAPSED, postTimer_.id());
    // "post" times the FXAA pass too, as on Vulkan.
    const bool posted = (merged ? mergedPostPass(frame, readBackHdr_, &message)
                                : postPass(frame, targets_.ldrFramebuffer.id(), &message)) &&
                        (!fxaa_ || fxaaPass(targets_.fxaaFramebuffer.id(), &message));
    if (timed_) glEndQuery(GL_TIME_ELAPSED);
    if (!posted) return false;
    if (readBackHdr_ && !merged) readHdr();
    if (fxaa_) {
      gl::readRgba8(targets_.fxaaFramebuffer.id(), GL_COLOR_ATTACHMENT0, frame.width, frame.height, &result->ldr);
    } else if (merged) {
      gl::readRgba8(targets_.mergedFramebuffer.id(), GL_COLOR_ATTACHMENT1, frame.width, frame.height, &result->ldr);
    } else {
      gl::readRgba8(targets_.ldrFramebuffer.id(), GL_COLOR_ATTACHMENT0, frame.width, frame.height, &result->ldr);
    }
    leaveState(0, frame.width, frame.height);
    result->width = frame.width;
    result->height = frame.height;
    result->hdrWidth = targets_.forwardWidth;
    result->hdrHeight = targets_.forwardHeight;
    result->bloom.clear();
    result->bloomWidth = result->bloomHeight = 0;
    result->bloomLevels = bloomOn_ ? bloomChain_.levelCount() : 0;
    if (bloomOn_ && readBackHdr_) bloomChain_.readLevel0(&result->bloom, &result->bloomWidth, &result->bloomHeight);
    result->gpuTimes.clear();
    if (timed_) {
      // Nanoseconds, waited for (GL_QUERY_RESULT). 64 bits: the 32-bit getter saturates at 4.3 s.
      GLuint64 forwardNs = 0, postNs = 0;
      context_->queryResult64()(forwardTimer_.id(), GL_QUERY_RESULT, &forwardNs);
      context_->queryResult64()(postTimer_.id(), GL_QUERY_RESULT, &postNs);
      result->gpuTimes.push_back({"forward", double(forwardNs) * 1e-6});
      result->gpuTimes.push_back({"post", double(postNs) * 1e-6});
    }
    return checkGlError("readback", &message);
  };
  return guarded(renderFrame, message, error);
}

// The post pass writes the app's framebuffer: on the separate path it draws into it; on the
// merged path the app's image is lent to the backend's merged framebuffer as colour 1 for this
// frame, except for the default framebuffer (nothing to attach), which takes the separate path.
bool GlBackend::renderToFramebuffer(const FrameDesc& frame, const GlAppTarget& target, std::string* error) {
  std::string message;
  const auto renderFrame = [&] {
    if (target.width == 0 || target.height == 0) {
      message = "the app's target has size " + std::to_string(target.width) + "x" + std::to_string(target.height);
      return false;
    }
    if (!checkShadowPass(frame, &message) || !beginFrame(frame, &message)) return false;
    // The app's framebuffer keeps GL's convention, bottom-up (gl_row_order.h).
    gl::AppAttachment attachment;
    if (!gl::inspectAppTarget(target, frame.width, frame.height, context_->isEs(), &attachment, &message)) {
      return false;
    }
    // FXAA: forward and post into the backend's targets, then FXAA into the app's framebuffer.
    if (fxaa_) {
      const bool ownMerged = path_ == PostPath::Merged;
      bool done = forwardPass(frame, ownMerged ? targets_.mergedFramebuffer.id() : targets_.hdrFramebuffer.id(),
                              ownMerged, gl::RowOrder::BottomUp, &message) &&
                  (ownMerged ? mergedPostPass(frame, false, &message)
                             : postPass(frame, targets_.ldrFramebuffer.id(), &message)) &&
                  fxaaPass(target.framebuffer, &message);
      leaveState(target.framebuffer, frame.width, frame.height);
      return done && checkGlError("drawing into the app's framebuffer", &message);
    }
    const bool merged = path_ == PostPath::Merged && attachment.type != GL_FRAMEBUFFER_DEFAULT;
    if (merged) {
      glBindFramebuffer(GL_FRAMEBUFFER, targets_.appMergedFramebuffer.id());
      if (!gl::attachAppImage(attachment, &message)) return false;
    }
    bool done = forwardPass(frame, merged ? targets_.appMergedFramebuffer.id() : targets_.hdrFramebuffer.id(), merged,
                            gl::RowOrder::BottomUp, &message);
    if (done) {
      done = merged ? mergedPostPass(frame, false, &message) : postPass(frame, target.framebuffer, &message);
    }
    if (merged) {
      glBindFramebuffer(GL_FRAMEBUFFER, targets_.appMergedFramebuffer.id());
      gl::detachAppImage(attachment);
    }
    leaveState(target.framebuffer, frame.width, frame.height);
    return done && checkGlError("drawing into the app's framebuffer", &message);
  };
  return guarded(renderFrame, message, error);
}

bool GlBackend::prepareTargets(uint32_t width, uint32_t height, std::string* error) {
  if (targets_.width == width && targets_.height == height) return true;
  const gl::Context::RenderToTexture* renderToTexture = renderToTexture_ ? &context_->renderToTexture() : nullptr;
  return gl::createRenderTargets(width, height, path_ == PostPath::Merged, hdrFormat_, samples_, renderToTexture, fxaa_,
                                 &targets_, error, renderScale_);
}

bool GlBackend::forwardPass(const FrameDesc& frame, GLuint framebuffer, bool merged, gl::RowOrder rows,
                            std::string* error) {
  if (!uploadInstances(frame, error)) return false;
  meshes_.beginFrame();
  materialBlocks_.beginFrame();
  if (frame.shadow && !shadowPass(frame, error)) return false;
  // MSAA: the forward pass draws into the multisampled framebuffer, resolved into `framebuffer`'s
  // HDR below; its only colour is the HDR samples.
  const bool msaa = samples_ > 1;
  glBindFramebuffer(GL_FRAMEBUFFER, msaa ? targets_.msaaFramebuffer.id() : framebuffer);
  // Merged: the forward pass writes colour 0 (HDR) only; LDR (colour 1) is the post pass's.
  const GLenum forwardBuffers[2] = {GL_COLOR_ATTACHMENT0, GL_NONE};
  glDrawBuffers(merged && !msaa ? 2 : 1, forwardBuffers);
  glViewport(0, 0, static_cast<GLsizei>(targets_.forwardWidth), static_cast<GLsizei>(targets_.forwardHeight));
  glDisable(GL_BLEND);
  // DrawItem::cullBackFaces: triangles counter-clockwise in GL's clip space are front faces; the
  // top-down clip (gl_row_order.h) mirrors the window, which makes them clockwise there.
  glFrontFace(rows == gl::RowOrder::TopDown ? GL_CW : GL_CCW);
  glCullFace(GL_BACK);
  glEnable(GL_DEPTH_TEST);
  // The environment is a cube map: GLES 3.0 filters across its faces always, desktop GL only
  // when asked (and GLES has no such enum). Set per pass: an app's context may have changed it.
  if (!context_->isEs()) glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);  // also required for the depth clear to take effect
  glClearBufferfv(GL_COLOR, 0, frame.clearColor);
  const GLfloat farDepth = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &farDepth);

  abi::FrameUniforms frameUniforms = frame.frame;
  if (rows == gl::RowOrder::TopDown) gl::topDownClip(frame.frame.viewProjection, frameUniforms.viewProjection);
  frameUniforms.cameraPosition[3] = msaa ? 1.0f : 0.0f;  // masked materials: alpha to coverage (shader_abi.h)
  glBindBuffer(GL_UNIFORM_BUFFER, frameUniforms_.id());
  glBufferData(GL_UNIFORM_BUFFER, sizeof(abi::FrameUniforms), &frameUniforms, GL_DYNAMIC_DRAW);
  glBindBufferBase(GL_UNIFORM_BUFFER, abi::kFrameBinding, frameUniforms_.id());
  // Every draw may read ShadowUniforms (the receivers do): zeros without a shadow pass.
  const abi::ShadowUniforms shadowUniforms = frame.shadow ? frame.shadow->uniforms : abi::ShadowUniforms{};
  glBindBuffer(GL_UNIFORM_BUFFER, shadowUniforms_.id());
  glBufferData(GL_UNIFORM_BUFFER, sizeof(abi::ShadowUniforms), &shadowUniforms, GL_DYNAMIC_DRAW);
  glBindBufferBase(GL_UNIFORM_BUFFER, abi::kShadowBinding, shadowUniforms_.id());
  if (!checkGlError("forward pass setup", error)) return false;

  // The receivers sample the atlas the shadow pass drew (every forward draw has it on its unit).
  textures_.setShadowAtlas(frame.shadow ? shadowAtlas_.texture() : 0, shadowAtlas_.sampler());
  firstInstance_ = 0;
  for (size_t i = 0; i < frame.draws.size(); ++i) {
    std::string drawError;
    if (!drawItem(frame, frame.draws[i], rows, &drawError)) {
      if (error) *error = "draw " + std::to_string(i) + ": " + drawError;
      glBindVertexArray(0);
      textures_.clearSamplers();
      return false;
    }
  }
  // Sampler objects are the forward draws' state (a material's wrap and filter modes): unbound here,
  // so that the passes after it (bloom, post) sample with their textures' own parameters.
  textures_.clearSamplers();
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glUseProgram(0);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  meshes_.endFrame();
  materialBlocks_.endFrame();
  if (msaa) {
    resolveSamples(targets_.forwardWidth, targets_.forwardHeight);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    return checkGlError("forward pass (MSAA resolve)", error);
  }

  // Separate path: depth is dead once the forward pass ends. Invalidating it here, before the
  // framebuffer switch, is what lets a tiler skip writing depth tiles to memory (DESIGN: depth is
  // never stored). Colour is kept: the post pass samples it. (Merged: the post pass invalidates.)
  if (!merged && context_->canInvalidateFramebuffer()) {
    const GLenum depthAttachment = GL_DEPTH_ATTACHMENT;
    glInvalidateFramebuffer(GL_FRAMEBUFFER, 1, &depthAttachment);
  }
  return checkGlError("forward pass", error);
}

// glBlitFramebuffer from multisampled to single-sample averages each pixel's samples (GLES 3.0
// requires equal formats for it). Then colour and depth samples are invalidated, so no later use
// keeps them (a tiler has written them out to blit them; the extension below avoids that).
// With GL_EXT_multisampled_render_to_texture the driver resolves into the texture when the
// framebuffer is flushed (the caller binds the next one); only depth is invalidated, since an
// invalidated colour would be discarded instead of resolved.
void GlBackend::resolveSamples(uint32_t width, uint32_t height) {
  if (targets_.renderToTexture) {
    if (context_->canInvalidateFramebuffer()) {
      const GLenum depth = GL_DEPTH_ATTACHMENT;
      glInvalidateFramebuffer(GL_FRAMEBUFFER, 1, &depth);
    }
    return;
  }
  const auto w = static_cast<GLint>(width);
  const auto h = static_cast<GLint>(height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, targets_.msaaFramebuffer.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets_.hdrFramebuffer.id());
  const GLenum colour0 = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &colour0);
  glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  if (context_->canInvalidateFramebuffer()) {
    const GLenum samples[2] = {GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT};
    glInvalidateFramebuffer(GL_READ_FRAMEBUFFER, 2, samples);
  }
}

bool GlBackend::uploadInstances(const FrameDesc& frame, std::string* error) {
  if (std::string why = instanceCountError(frame); !why.empty()) {
    if (error) *error = why;
    return false;
  }
  std::vector<abi::InstanceTransform> instances;
  for (const DrawItem& draw : FrameDraws(frame))
    instances.insert(instances.end(), draw.instances.begin(), draw.instances.end());
  glBindBuffer(GL_ARRAY_BUFFER, instances_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances.size() * sizeof(abi::InstanceTransform)),
               instances.data(), GL_STREAM_DRAW);
  return checkGlError("instance upload", error);
}

// GL's depth offset is factor × m + units × r (GLES 3.0 spec, "Depth Offset"), m the polygon's
// largest window-depth slope per pixel, r the smallest window-depth difference that stays
// distinct in the depth buffer: implementation-dependent, but constant over a fixed-point
// buffer's range, and for an n-bit one no smaller than one step, 2^-n (Mesa's llvmpipe takes
// 1 / (2^16 - 1) for D16). So a bias of d in window depth is d / 2^-16 units, as on Vulkan, whose
// spec fixes r at 2^-n.
constexpr float kD16BiasUnit = 1.0f / 65536.0f;

bool GlBackend::shadowPass(const FrameDesc& frame, std::string* error) {
  const ShadowPassDesc& shadow = *frame.shadow;
  bool remade = false;
  if (!shadowAtlas_.ensure(shadow.atlasSize, &remade, error)) return false;
  if (remade) textures_.forgetBindings();  // the old atlas's name may come back for another texture
  glBindFramebuffer(GL_FRAMEBUFFER, shadowAtlas_.framebuffer());
  const auto side = static_cast<GLsizei>(shadow.atlasSize);
  glViewport(0, 0, side, side);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);  // also required for the depth clear to take effect
  const GLfloat farDepth = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &farDepth);
  // The views keep GL's clip y, so atlas row r is window y = r (runtime/sun_shadow.h) and a
  // triangle facing the sun is counter-clockwise in this window, as one facing the camera is in
  // the forward pass's: the same front face, no flip to undo.
  glFrontFace(GL_CCW);
  glCullFace(GL_BACK);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_POLYGON_OFFSET_FILL);
  textures_.setShadowAtlas(0, 0);  // the casters draw into the atlas: the dummy on its unit
  // The casters' instances follow the forward draws' in the frame's upload.
  firstInstance_ = 0;
  for (const DrawItem& draw : frame.draws) firstInstance_ += draw.instances.size();
  bool drawn = true;
  for (const ShadowCascadeDesc& view : shadow.cascades) {
    if (!(drawn = drawShadowView(frame, view, error))) break;
  }
  glBindVertexArray(0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  return drawn && checkGlError("shadow pass", error);
}

bool GlBackend::drawShadowView(const FrameDesc& frame, const ShadowCascadeDesc& view, std::string* error) {
  // The camera's frame block with the view's matrix; a masked caster's alpha test discards by its
  // coverage alone (cameraPosition.w = 0: no alpha to coverage in the single-sample atlas).
  abi::FrameUniforms viewUniforms = frame.frame;
  std::copy(std::begin(view.viewProjection), std::end(view.viewProjection), std::begin(viewUniforms.viewProjection));
  viewUniforms.cameraPosition[3] = 0.0f;
  setVertexSlopeBias(view, 2.0f, &viewUniforms);  // GL's clip depth spans [-1, 1]
  glBindBuffer(GL_UNIFORM_BUFFER, frameUniforms_.id());
  glBufferData(GL_UNIFORM_BUFFER, sizeof(abi::FrameUniforms), &viewUniforms, GL_DYNAMIC_DRAW);
  glBindBufferBase(GL_UNIFORM_BUFFER, abi::kFrameBinding, frameUniforms_.id());
  const auto x = static_cast<GLint>(view.viewport[0]);
  const auto y = static_cast<GLint>(view.viewport[1]);
  const auto width = static_cast<GLsizei>(view.viewport[2]);
  const auto height = static_cast<GLsizei>(view.viewport[3]);
  glViewport(x, y, width, height);
  glScissor(x, y, width, height);
  glPolygonOffset(view.slopeBias, view.depthBias / kD16BiasUnit);
  for (uint32_t caster : view.casters) {
    std::string drawError;
    if (!drawItem(frame, frame.shadow->casters[caster], gl::RowOrder::BottomUp, &drawError, true)) {
      if (error) *error = "shadow caster " + std::to_string(caster) + ": " + drawError;
      return false;
    }
  }
  return true;
}

bool GlBackend::drawItem(const FrameDesc& frame, const DrawItem& item, gl::RowOrder rows, std::string* error,
                         bool caster) {
  if (!item.mesh || !item.program) {
    if (error) *error = item.mesh ? "no shader program" : "no mesh";
    return false;
  }
  CachedProgram* cached = programFor(*item.program, error);
  if (!cached) return false;
  const gl::LinkedProgram* program = &cached->linked;

  // A block larger than the data bound to it reads past the buffer: refuse rather than draw.
  if (program->frame.dataSize > static_cast<GLint>(sizeof(abi::FrameUniforms)) ||
      program->object.dataSize > static_cast<GLint>(sizeof(abi::ObjectUniforms)) ||
      program->shadow.dataSize > static_cast<GLint>(sizeof(abi::ShadowUniforms))) {
    if (error) {
      *error = "shader's FrameUniforms/ObjectUniforms/ShadowUniforms blocks (" +
               std::to_string(program->frame.dataSize) + "/" + std::to_string(program->object.dataSize) + "/" +
               std::to_string(program->shadow.dataSize) + " bytes) are larger than the ABI's (" +
               std::to_string(sizeof(abi::FrameUniforms)) + "/" + std::to_string(sizeof(abi::ObjectUniforms)) + "/" +
               std::to_string(sizeof(abi::ShadowUniforms)) + ")";
    }
    return false;
  }
  if (program->material.present() && materialBytes(item).size() < static_cast<size_t>(program->material.dataSize)) {
    if (error) {
      *error = "shader's MaterialParams block is " + std::to_string(program->material.dataSize) +
               " bytes but the draw supplies " + std::to_string(materialBytes(item).size());
    }
    return false;
  }

  const gl::MeshBuffers* mesh = meshes_.resident(*item.mesh, error);
  if (!mesh) return false;

  // One buffer per block, re-specified per draw: glBufferData gives the driver fresh storage
  // while earlier draws still read the old contents.
  glBindBuffer(GL_UNIFORM_BUFFER, objectUniforms_.id());
  const abi::ObjectUniforms object = objectUniforms(mesh->decode);
  glBufferData(GL_UNIFORM_BUFFER, sizeof(abi::ObjectUniforms), &object, GL_DYNAMIC_DRAW);
  glBindBufferBase(GL_UNIFORM_BUFFER, abi::kObjectBinding, objectUniforms_.id());
  if (rows == gl::RowOrder::TopDown && item.program == &backgroundProgram() &&
      materialBytes(item).size() >= sizeof(abi::BackgroundParams)) {
    // The background's triangle is at GL's normalized device coordinates, not through the frame's
    // view-projection: its direction matrix takes the top-down y instead.
    abi::BackgroundParams params;
    std::memcpy(&params, materialBytes(item).data(), sizeof params);
    gl::topDownBackground(&params);
    glBindBuffer(GL_UNIFORM_BUFFER, materialUniforms_.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof params, &params, GL_DYNAMIC_DRAW);
    glBindBufferBase(GL_UNIFORM_BUFFER, abi::kMaterialBinding, materialUniforms_.id());
  } else if (item.materialBlock && !item.materialBlock->bytes.empty()) {
    glBindBufferBase(GL_UNIFORM_BUFFER, abi::kMaterialBinding, materialBlocks_.resident(*item.materialBlock));
  } else if (!item.materialParams.empty()) {
    glBindBuffer(GL_UNIFORM_BUFFER, materialUniforms_.id());
    glBufferData(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(item.materialParams.size()), item.materialParams.data(),
                 GL_DYNAMIC_DRAW);
    glBindBufferBase(GL_UNIFORM_BUFFER, abi::kMaterialBinding, materialUniforms_.id());
  }

  if (item.cullBackFaces)
    glEnable(GL_CULL_FACE);
  else
    glDisable(GL_CULL_FACE);
  // Masked materials under MSAA write their coverage as alpha (output_blending.glsl).
  if (item.masked && samples_ > 1 && !caster)
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  else
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  // Premultiplied colour for the blended modes; they test depth but do not write it.
  // The background (at the far plane) passes where depth is still the cleared 1 and writes none.
  glDepthFunc(item.atFarPlane ? GL_LEQUAL : GL_LESS);
  if (item.blending == Blending::Opaque) {
    glDisable(GL_BLEND);
    glDepthMask(item.atFarPlane ? GL_FALSE : GL_TRUE);
  } else {
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, item.blending == Blending::Transparent ? GL_ONE_MINUS_SRC_ALPHA : GL_ONE);
    glDepthMask(GL_FALSE);
  }
  glUseProgram(program->program.id());
  // Sampler uniforms are program state (set while the program is in use); units are per draw.
  gl::assignSamplerUnits(program->program.id(), frame.frameTextures, &cached->samplerUnits);
  gl::assignSamplerUnits(program->program.id(), item.textures, &cached->samplerUnits);
  textures_.bind(frame, item);
  glBindVertexArray(mesh->vertexArray.id());
  glBindBuffer(GL_ARRAY_BUFFER, instances_.id());
  for (const abi::VertexAttribute& a : abi::kInstanceAttributes) {
    const size_t offset = firstInstance_ * sizeof(abi::InstanceTransform) + a.offsetFloats * sizeof(float);
    glVertexAttribPointer(a.location, 4, GL_FLOAT, GL_FALSE, sizeof(abi::InstanceTransform),
                          reinterpret_cast<const void*>(offset));
  }
  const auto instanceCount = static_cast<GLsizei>(item.instances.size());
  firstInstance_ += item.instances.size();
  glDrawElementsInstanced(GL_TRIANGLES, mesh->indexCount, GL_UNSIGNED_INT, nullptr, instanceCount);
  return checkGlError("draw", error);
}

GlBackend::CachedProgram* GlBackend::programFor(const ShaderProgram& program, std::string* error) {
  auto found = programs_.find(&program);
  if (found != programs_.end() && found->second.vertexSource == program.vertexGlslEs &&
      found->second.fragmentSource == program.fragmentGlslEs) {
    found->second.lastUsedFrame = programFrame_;
    return &found->second;
  }
  std::optional<gl::LinkedProgram> linked = gl::buildProgram(program.vertexGlslEs, program.fragmentGlslEs, error);
  const package::ProgramInterface* declared = program.interface ? &*program.interface : nullptr;
  if (!linked) {
    if (declared && error)
      *error = "material '" + declared->material + "' variant " + declared->variant + ": " + *error;
    return nullptr;
  }
  // A package's GLSL ES is code the app did not build: its reflection against what the draws bind
  // (the same check the core ran on its SPIR-V; the linker has matched the stages already).
  if (declared) {
    const std::string why = package::interfaceError(
        *declared, gl::reflectProgram(linked->program.id(), context_->resourceQueries()), false);
    if (!why.empty()) {
      if (error) *error = why;
      return nullptr;
    }
  }
  CachedProgram& cached = programs_[&program];
  cached.vertexSource = program.vertexGlslEs;
  cached.fragmentSource = program.fragmentGlslEs;
  cached.linked = std::move(*linked);
  cached.samplerUnits.clear();  // a new program: every sampler uniform starts at unit 0
  cached.lastUsedFrame = programFrame_;
  ++programBuilds_;
  // The ABI's frame samplers get their units once, at link, whether or not a frame binds them: a
  // sampler left at unit 0 would share it with facet_dfgLut, and a samplerCube (the environment)
  // beside a sampler2D on one unit makes a draw invalid (GL_INVALID_OPERATION).
  static const std::vector<TextureBinding> abiFrameSamplers = [] {
    std::vector<TextureBinding> bindings;
    for (const abi::SamplerDesc& s : abi::kFrameSamplers) bindings.push_back({s.binding, std::string(s.name), nullptr});
    bindings.push_back({abi::kShadowAtlasBinding, abi::kShadowAtlasName, nullptr});
    return bindings;
  }();
  glUseProgram(cached.linked.program.id());  // drawItem uses it next anyway
  gl::assignSamplerUnits(cached.linked.program.id(), abiFrameSamplers, &cached.samplerUnits);
  return &cached;
}

// Merged path: the post pass draws into the same framebuffer, reading each pixel's HDR value by
// framebuffer fetch (colour 0, declared inout) and writing LDR to colour 1; then HDR (unless read
// back) and depth are invalidated, so a tiler never writes them to memory.
bool GlBackend::mergedPostPass(const FrameDesc& frame, bool keepHdr, std::string* error) {
  const GLenum postBuffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, postBuffers);
  glDisable(GL_DEPTH_TEST);  // the triangle covers every pixel
  glDisable(GL_BLEND);       // the last forward draw may have been blended
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  glUseProgram(post_.program.id());
  if (!postInputs_.bind(frame, error)) return false;
  textures_.forgetBindings();  // the LUT's unit is a forward texture's too
  glBindVertexArray(emptyVertexArray_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);  // full-screen triangle from gl_VertexID
  glBindVertexArray(0);
  glUseProgram(0);
  if (context_->canInvalidateFramebuffer()) {
    const GLenum dead[2] = {GL_DEPTH_ATTACHMENT, GL_COLOR_ATTACHMENT0};
    glInvalidateFramebuffer(GL_FRAMEBUFFER, keepHdr ? 1 : 2, dead);
  }
  return checkGlError("post pass (framebuffer fetch)", error);
}

bool GlBackend::postPass(const FrameDesc& frame, GLuint framebuffer, std::string* error) {
  // Separate path: a second pass that samples the stored HDR target. A merged backend runs this
  // pass only for frames into the app's default framebuffer. Bloom's chain runs first (the
  // threshold reads the block the post inputs bind).
  if (bloomOn_ && (!bloomChain_.ensureTargets(targets_.forwardWidth, targets_.forwardHeight, error) ||
                   !postInputs_.bind(frame, error) || !bloomChain_.run(targets_.hdrColor, error)))
    return false;
  return sampledPass(framebuffer, path_ == PostPath::Merged ? sampledPost_ : post_, targets_.hdrColor, &frame,
                     "post pass", error);
}

bool GlBackend::sampledPass(GLuint framebuffer, const gl::LinkedProgram& program, const gl::Texture& input,
                            const FrameDesc* postFrame, const char* what, std::string* error) {
  // The app's framebuffer keeps the draw buffers the app gave it.
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, static_cast<GLsizei>(targets_.width), static_cast<GLsizei>(targets_.height));
  glDisable(GL_DEPTH_TEST);  // the LDR target has no depth; the triangle covers every pixel
  glDisable(GL_BLEND);       // the last forward draw may have been blended
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  glUseProgram(program.program.id());
  glActiveTexture(GL_TEXTURE0 + abi::kPostHdrBinding);
  glBindTexture(GL_TEXTURE_2D, input.id());
  if (postFrame && !postInputs_.bind(*postFrame, error)) return false;
  if (postFrame && bloomOn_) {
    glActiveTexture(GL_TEXTURE0 + abi::kPostBloomBinding);
    glBindTexture(GL_TEXTURE_2D, bloomChain_.level0().id());
  }
  textures_.forgetBindings();  // units 0 (and the LUT's) no longer hold what the last draw bound
  glBindVertexArray(emptyVertexArray_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);  // full-screen triangle from gl_VertexID
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
  return checkGlError(what, error);
}

}  // namespace

std::unique_ptr<GlRenderer> createGlBackend(std::unique_ptr<GlContext> context, const GlOptions& options,
                                            std::string* error) {
  // Nothing here throws by design; the catch keeps the never-throws contract if allocation fails.
  try {
    return GlBackend::create(std::move(context), options, error);
  } catch (const std::exception& e) {
    if (error) *error = std::string("GL backend: ") + e.what();
    return nullptr;
  }
}

}  // namespace facet::runtime
