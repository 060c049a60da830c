#include <string>

#include "facet/render_backend.h"

namespace facet::runtime {

const PostShaders* findPostShaders(const PostSettings& settings, std::string* error) {
  std::string available;
  for (const PostShaders& variant : postVariants()) {
    if (variant.effects == settings) return &variant;
    available += std::string(available.empty() ? "" : ", ") + variant.effects.toneCurve +
                 (variant.effects.dither ? " with dithering" : "");
  }
  if (error)
    *error = "no post variant with tone curve '" + settings.toneCurve + "'" + (settings.dither ? " and dithering" : "") +
             " (built in: " + available + ")";
  return nullptr;
}

}  // namespace facet::runtime
