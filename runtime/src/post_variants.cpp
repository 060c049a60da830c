#include <string>

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

const PostShaders* findPostShaders(const PostSettings& settings, std::string* error) {
  std::string available;
  for (const PostShaders& variant : postVariants()) {
    if (variant.effects == settings) return &variant;
    if (variant.effects.dither || variant.effects.colorGrading || variant.effects.vignette || variant.effects.bloom)
      continue;  // listed by tone curve
    available += std::string(available.empty() ? "" : ", ") + variant.effects.toneCurve;
  }
  if (error)
    *error = "no post variant with tone curve '" + settings.toneCurve + "'" +
             (settings.colorGrading ? ", colour grading" : "") + (settings.vignette ? ", vignette" : "") +
             (settings.dither ? ", dithering" : "") + (settings.bloom ? ", bloom" : "") + " (built in: tone curves " +
             available + ", each with any of colour grading, vignette, dithering and bloom)";
  return nullptr;
}

}  // namespace facet::runtime
