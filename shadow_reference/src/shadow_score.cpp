#include "facet/shadow_reference/shadow_score.h"

#include <cmath>

namespace facet::shadow_reference {

ReferenceCounts countReference(const ReferenceImage& image) {
  ReferenceCounts c;
  for (const ReferencePixel& p : image.pixels) {
    if (p.kind == PixelKind::Sky)
      ++c.sky;
    else if (p.kind == PixelKind::FacesAway)
      ++c.facesAway;
    else if (p.footprint == 1)
      ++c.lit;
    else if (p.footprint == 0)
      ++c.occluded;
    else
      ++c.partial;
  }
  return c;
}

std::optional<ShadowScore> scoreShadows(const ReferenceImage& reference, const RenderedVisibility& rendered,
                                        std::string* error) {
  if (rendered.width != reference.width || rendered.height != reference.height ||
      rendered.values.size() != reference.pixels.size()) {
    *error = "the rendered image is " + std::to_string(rendered.width) + "x" + std::to_string(rendered.height) +
             ", the scene's " + std::to_string(reference.width) + "x" + std::to_string(reference.height);
    return std::nullopt;
  }
  ShadowScore s;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    const ReferencePixel& p = reference.pixels[i];
    if (p.kind != PixelKind::Surface || (p.footprint != 0 && p.footprint != 1)) continue;
    const float v = rendered.values[i];
    if (std::isnan(v)) {
      ++s.unmeasured;
      continue;
    }
    ++s.scored;
    const bool renderedLit = v >= kLitThreshold;
    if (renderedLit && p.footprint == 0) ++s.leaks;
    if (!renderedLit && p.footprint == 1) ++s.acne;
  }
  s.wrong = s.leaks + s.acne;
  return s;
}

}  // namespace facet::shadow_reference
