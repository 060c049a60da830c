// The shadow accuracy metric: a rendered visibility image scored against the ray-cast reference
// (docs/shadows.md, "Accuracy: the ray-cast reference"). Only pixels whose reference visibility
// over the filter's footprint is exactly 0 or 1 are scored: inside a penumbra the filter's
// answer is a blend, not an error.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/shadow_reference/reference_image.h"

namespace facet::shadow_reference {

// What the renderer says per pixel: visibility in [0, 1], or NaN where its frames cannot tell
// (renderedVisibilityFromFrames). Rows top to bottom.
struct RenderedVisibility {
  uint32_t width = 0, height = 0;
  std::vector<float> values;
};

// A rendered visibility of at least this is lit.
inline constexpr double kLitThreshold = 0.5;

struct ReferenceCounts {
  uint64_t sky = 0, facesAway = 0;
  uint64_t lit = 0, occluded = 0, partial = 0;  // Surface pixels by footprint visibility: 1, 0, between
};
ReferenceCounts countReference(const ReferenceImage& image);

struct ShadowScore {
  uint64_t scored = 0;      // Surface pixels with footprint visibility 0 or 1, measurable in the rendering
  uint64_t wrong = 0;       // leaks + acne
  uint64_t leaks = 0;       // rendered lit where the reference is occluded (light leaks, peter-panning)
  uint64_t acne = 0;        // rendered occluded where the reference is lit (acne, over-wide shadows)
  uint64_t unmeasured = 0;  // scorable by the reference, but NaN in the rendering
  double wrongFraction() const { return scored ? double(wrong) / double(scored) : 0; }
};

// Nullopt with *error when the sizes differ.
std::optional<ShadowScore> scoreShadows(const ReferenceImage& reference, const RenderedVisibility& rendered,
                                        std::string* error);

}  // namespace facet::shadow_reference
