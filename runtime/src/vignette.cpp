#include "facet/runtime/vignette.h"

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

abi::PostUniforms postUniforms(const VignetteSettings& v, uint32_t width, uint32_t height) {
  abi::PostUniforms u{};
  u.vignette[0] = float(v.intensity);
  u.vignette[1] = float(v.radius);
  u.vignette[2] = float(v.smoothness);
  u.vignette[3] = float(v.roundness);
  if (width == 0 || height == 0) return u;
  u.viewport[0] = 1.0f / float(width);
  u.viewport[1] = 1.0f / float(height);
  u.viewport[2] = float(width) / float(height);
  return u;
}

abi::PostUniforms postUniformsFor(const FrameDesc& frame, bool viewport, const BloomSettings* bloom) {
  abi::PostUniforms u = frame.postUniforms;
  if (viewport && frame.width > 0 && frame.height > 0) {
    u.viewport[0] = 1.0f / float(frame.width);
    u.viewport[1] = 1.0f / float(frame.height);
  }
  if (bloom) {
    u.bloom[0] = float(bloom->intensity);
    u.bloom[1] = float(bloom->threshold);
    u.bloom[2] = float(bloom->threshold * 0.5);  // the soft knee's half width (chunks/bloom.glsl)
    u.bloom[3] = 0.0f;
  }
  return u;
}

}  // namespace facet::runtime
