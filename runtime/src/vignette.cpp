#include "facet/runtime/vignette.h"

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

}  // namespace facet::runtime
