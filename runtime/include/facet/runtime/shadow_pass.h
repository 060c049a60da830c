// The shadow pass a backend draws (render_backend.h ShadowPassDesc), from a scene's sun and spot
// lights that cast and the bounds of its casters (docs/shadows.md, "Shadow pass"): one view per
// cascade and per casting spot light, each its rectangle of the atlas, its matrix, the casters it
// can see and its biases, which both backends iterate alike.
#pragma once

#include <vector>

#include "facet/runtime/render_backend.h"
#include "facet/runtime/sun_shadow.h"
#include "facet/scene/scene.h"

namespace facet::runtime {

// `bounds[i]` bounds `casters[i]`. The sun's cascades first (when it casts), then one view per
// spot light of shadowSpotLights(scene), in the cells the atlas layout gives them (spot_shadow.h).
ShadowPassDesc shadowPassDesc(const Scene& scene, const std::vector<CasterBounds>& bounds,
                              std::vector<DrawItem> casters);

}  // namespace facet::runtime
