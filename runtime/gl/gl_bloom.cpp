#include "gl_bloom.h"

#include <optional>

#include "gl_post_inputs.h"
#include "gl_targets.h"

namespace facet::runtime::gl {
namespace {

bool buildBloomProgram(const std::string& vertex, const std::string& fragment, bool readsBlock, LinkedProgram* out,
                       std::string* error) {
  std::string buildError;
  std::optional<LinkedProgram> built = buildProgram(vertex, fragment, &buildError);
  if (!built) {
    *error = "bloom shaders: " + buildError;
    return false;
  }
  *out = std::move(*built);
  const GLuint program = out->program.id();
  glUseProgram(program);
  const GLint source = glGetUniformLocation(program, std::string(abi::kBloomSourceName).c_str());
  if (source < 0) {
    *error = "bloom fragment shader has no sampler uniform '" + std::string(abi::kBloomSourceName) + "'";
    glUseProgram(0);
    return false;
  }
  glUniform1i(source, GLint(abi::kPostHdrBinding));
  glUseProgram(0);
  if (readsBlock && !bindPostBlock(program, "bloom threshold shader", error)) return false;
  return checkGlError("bloom programs", error);
}

void setLinear(GLuint texture) {
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

}  // namespace

bool BloomChain::init(HdrFormat format, const BloomSettings& bloom, std::string* error) {
  format_ = format;
  settings_ = bloom;
  const BloomShaders& shaders = bloomShaders();
  emptyVertexArray_ = VertexArray::generate();
  return buildBloomProgram(shaders.vertexGlslEs, shaders.downsampleGlslEs, false, &down_, error) &&
         (bloom.threshold <= 0 ||
          buildBloomProgram(shaders.vertexGlslEs, shaders.thresholdGlslEs, true, &threshold_, error)) &&
         buildBloomProgram(shaders.vertexGlslEs, shaders.upsampleGlslEs, false, &up_, error);
}

bool BloomChain::ensureTargets(uint32_t width, uint32_t height, std::string* error) {
  if (width == width_ && height == height_ && !levels_.empty()) return true;
  levels_.clear();
  width_ = height_ = 0;
  const bool packed = format_ == HdrFormat::R11G11B10Float;
  for (const ImageSize& size : bloomLevelSizes(width, height, settings_.levels)) {
    Level level;
    level.width = size.width;
    level.height = size.height;
    level.texture = Texture::generate();
    glBindTexture(GL_TEXTURE_2D, level.texture.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(hdrInternalFormat(format_)), GLsizei(size.width), GLsizei(size.height), 0,
                 packed ? GL_RGB : GL_RGBA, packed ? GL_UNSIGNED_INT_10F_11F_11F_REV : GL_HALF_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    level.framebuffer = Framebuffer::generate();
    glBindFramebuffer(GL_FRAMEBUFFER, level.framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, level.texture.id(), 0);
    if (!checkComplete("bloom", error)) {
      levels_.clear();
      return false;
    }
    levels_.push_back(std::move(level));
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  width_ = width;
  height_ = height;
  return checkGlError("bloom targets", error);
}

bool BloomChain::run(const Texture& hdr, std::string* error) {
  const auto n = uint32_t(levels_.size());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glBindVertexArray(emptyVertexArray_.id());
  glActiveTexture(GL_TEXTURE0 + abi::kPostHdrBinding);
  setLinear(hdr.id());  // texelFetch in the post pass ignores the filter
  const auto draw = [&](uint32_t level, const LinkedProgram& program, GLuint source) {
    glBindFramebuffer(GL_FRAMEBUFFER, levels_[level].framebuffer.id());
    const GLenum colour0 = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &colour0);
    glViewport(0, 0, GLsizei(levels_[level].width), GLsizei(levels_[level].height));
    glUseProgram(program.program.id());
    glBindTexture(GL_TEXTURE_2D, source);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  };
  glDisable(GL_BLEND);
  for (uint32_t i = 0; i < n; ++i)
    draw(i, i == 0 && settings_.threshold > 0 ? threshold_ : down_, i == 0 ? hdr.id() : levels_[i - 1].texture.id());
  // up_i = w · down_i + (1 − w) · tent(up_{i+1}), w = 1 / (n − i) (chunks/bloom.glsl).
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE_MINUS_CONSTANT_ALPHA, GL_CONSTANT_ALPHA);
  for (uint32_t i = n - 1; i-- > 0;) {
    const float w = 1.0f / float(n - i);
    glBlendColor(w, w, w, w);
    draw(i, up_, levels_[i + 1].texture.id());
  }
  glDisable(GL_BLEND);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindVertexArray(0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return checkGlError("bloom passes", error);
}

void BloomChain::readLevel0(std::vector<float>* rgba, uint32_t* width, uint32_t* height) const {
  *width = levels_[0].width;
  *height = levels_[0].height;
  readRgbaFloat(levels_[0].framebuffer.id(), GL_COLOR_ATTACHMENT0, *width, *height, rgba);
}

}  // namespace facet::runtime::gl
