// The bloom chain on GL (chunks/bloom.glsl, render_path.h), as on Vulkan (vk_bloom.h): a
// downsample into each level from the HDR texture, then an upsample into each level but the last
// with the constant blend (weight 1 / (levels − i) for the finer level's own blur); the post pass
// samples level 0 on unit abi::kPostBloomBinding. Textures in the HDR format, bilinear, clamped,
// remade when the HDR size changes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/render_backend.h"
#include "gl_objects.h"
#include "gl_program.h"

namespace facet::runtime::gl {

class BloomChain {
 public:
  // Builds the programs (fails when the context rejects the build-time shaders).
  bool init(HdrFormat format, const BloomSettings& bloom, std::string* error);
  // Makes the levels for an HDR texture of width × height (bloomLevelSizes) when the size changed.
  bool ensureTargets(uint32_t width, uint32_t height, std::string* error);
  // Runs the passes from `hdr` (its filter is set to bilinear); the PostUniforms block must be bound
  // at abi::kPostUniformsBinding for the threshold. Leaves blending off and no framebuffer bound.
  bool run(const Texture& hdr, std::string* error);
  // Level 0 as RGBA floats, rows top to bottom.
  void readLevel0(std::vector<float>* rgba, uint32_t* width, uint32_t* height) const;

  const Texture& level0() const { return levels_[0].texture; }
  uint32_t levelCount() const { return uint32_t(levels_.size()); }

 private:
  struct Level {
    Texture texture;
    Framebuffer framebuffer;
    uint32_t width = 0;
    uint32_t height = 0;
  };
  HdrFormat format_ = HdrFormat::Rgba16Float;
  BloomSettings settings_;
  LinkedProgram down_, threshold_, up_;
  VertexArray emptyVertexArray_;
  uint32_t width_ = 0, height_ = 0;
  std::vector<Level> levels_;
};

}  // namespace facet::runtime::gl
