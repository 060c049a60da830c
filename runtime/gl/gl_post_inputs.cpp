#include "gl_post_inputs.h"

#include "facet/runtime/content_hash.h"
#include "facet/runtime/vignette.h"

namespace facet::runtime::gl {

bool bindPostBlock(GLuint program, const std::string& what, std::string* error) {
  const std::string name(abi::kPostBlock.name);
  const GLuint index = glGetUniformBlockIndex(program, name.c_str());
  if (index == GL_INVALID_INDEX) {
    *error = what + " has no uniform block '" + name + "'";
    return false;
  }
  glUniformBlockBinding(program, index, abi::kPostUniformsBinding);
  return true;
}

namespace {
constexpr GLsizei kLutSize = GLsizei(abi::kColorLutSize);
constexpr size_t kLutValues = size_t(kLutSize) * kLutSize * kLutSize * 4;
}  // namespace

bool PostInputs::init(GLuint program, const PostSettings& effects, bool upscale, std::string* error) {
  effects_ = effects;
  upscale_ = upscale;
  if (effects.colorGrading) {
    lut_ = Texture::generate();
    glBindTexture(GL_TEXTURE_3D, lut_.id());
    // Trilinear, one level, clamped: the shader keeps to the lattice's texel centres.
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA16F, kLutSize, kLutSize, kLutSize, 0, GL_RGBA, GL_HALF_FLOAT, nullptr);
    glBindTexture(GL_TEXTURE_3D, 0);
  }
  if (readsBlock()) {
    uniforms_ = Buffer::generate();
    glBindBuffer(GL_UNIFORM_BUFFER, uniforms_.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(abi::PostUniforms), nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
  }
  return pointProgram(program, error);
}

bool PostInputs::pointProgram(GLuint program, std::string* error) {
  glUseProgram(program);
  if (effects_.bloom) {
    const GLint location = glGetUniformLocation(program, abi::kPostBloomName);
    if (location < 0) {
      *error = std::string("post-pass fragment shader has no sampler uniform '") + abi::kPostBloomName + "'";
      glUseProgram(0);
      return false;
    }
    glUniform1i(location, GLint(abi::kPostBloomBinding));  // the backend binds the chain's level 0 there
  }
  if (effects_.colorGrading) {
    const GLint location = glGetUniformLocation(program, abi::kPostColorLutName);
    if (location < 0) {
      *error = std::string("post-pass fragment shader has no sampler uniform '") + abi::kPostColorLutName + "'";
      glUseProgram(0);
      return false;
    }
    glUniform1i(location, GLint(abi::kPostColorLutBinding));  // program state: once
  }
  glUseProgram(0);
  if (readsBlock() && !bindPostBlock(program, "post-pass fragment shader", error)) return false;
  return checkGlError("post-pass effect inputs", error);
}

bool PostInputs::bind(const FrameDesc& frame, std::string* error) {
  if (effects_.colorGrading) {
    if (!frame.colorLut || frame.colorLut->rgba.size() != kLutValues) {
      *error = "the post variant grades colour, so the frame needs a colorLut of " + std::to_string(kLutSize) +
               "³ RGBA16F texels";
      return false;
    }
    glActiveTexture(GL_TEXTURE0 + abi::kPostColorLutBinding);
    glBindTexture(GL_TEXTURE_3D, lut_.id());
    const uint64_t hash = hashBytes(frame.colorLut->rgba.data(), kLutValues * sizeof(uint16_t));
    if (!lutUploaded_ || hash != lutHash_) {
      glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
      glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, kLutSize, kLutSize, kLutSize, GL_RGBA, GL_HALF_FLOAT,
                      frame.colorLut->rgba.data());
      lutHash_ = hash;
      lutUploaded_ = true;
    }
  }
  if (readsBlock()) {
    const abi::PostUniforms uniforms =
        postUniformsFor(frame, effects_.bloom || upscale_, effects_.bloom ? &bloom_ : nullptr);
    glBindBufferBase(GL_UNIFORM_BUFFER, abi::kPostUniformsBinding, uniforms_.id());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(abi::PostUniforms), &uniforms);
  }
  return checkGlError("post-pass effect inputs", error);
}

}  // namespace facet::runtime::gl
