// What the GL post pass reads besides HDR, for the effects its variant runs (PostSettings): the
// colour-grading LUT, a GL_TEXTURE_3D RGBA16F sampled trilinearly on unit
// abi::kPostColorLutBinding, and the PostUniforms block at uniform buffer binding
// abi::kPostUniformsBinding. The LUT is uploaded when the frame's bytes differ from the last
// upload's (content hash); the block is rewritten every frame.
#pragma once

#include <cstdint>
#include <string>

#include "facet/runtime/render_backend.h"
#include "gl_objects.h"

namespace facet::runtime::gl {

// Points a post-pass program's PostUniforms block at abi::kPostUniformsBinding; `what` names the
// shader in the error when the program has no such block. Leaves the program unbound.
bool bindPostBlock(GLuint program, const std::string& what, std::string* error);

class PostInputs {
 public:
  // Points the linked post program's LUT sampler and block at their units/bindings and creates
  // the texture and buffer its effects need. Fails when the program lacks one of them.
  // upscale: the upscaled form (render scale < 1), which reads the output's size from the block.
  bool init(GLuint program, const PostSettings& effects, bool upscale, std::string* error);
  // Points one more post program of the same effects (the merged backend's sampled fallback) at
  // the same units and bindings.
  bool pointProgram(GLuint program, std::string* error);
  // Uploads what changed and binds both for the post pass's draw. Changes the active texture unit.
  bool bind(const FrameDesc& frame, std::string* error);
  // Bloom's parameters, written into the block's `bloom` whatever the frame says.
  void setBloom(const BloomSettings& bloom) { bloom_ = bloom; }

 private:
  PostSettings effects_;
  bool upscale_ = false;
  BloomSettings bloom_;
  bool readsBlock() const { return effects_.vignette || effects_.bloom || upscale_; }
  Texture lut_;
  Buffer uniforms_;
  uint64_t lutHash_ = 0;
  bool lutUploaded_ = false;
};

}  // namespace facet::runtime::gl
