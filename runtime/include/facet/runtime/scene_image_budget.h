// The memory a scene's images take once decoded, bounded per scene before any is decoded: each
// image is within its own limit (image_texture.h: 8192 a side), but eight distinct 8192² textures
// took 8.5 GB and 108 s before this check (the hostile-input issue's measurement).
#pragma once

#include <cstdint>
#include <string>

#include "facet/scene/scene.h"

namespace facet::runtime {

// Decoded bytes a scene may use for its images (docs/security.md, "Limits"): a mobile app's
// whole texture budget is of this order, and a scene that needs more is a mistake or an attack.
inline constexpr uint64_t kMaxSceneImageBytes = uint64_t(512) << 20;

// What the scene's images decode to, from their headers only: RGBA8 with a full mip chain (4/3 of
// level 0) per distinct PNG texture, the bytes of its levels per KTX2 texture (ASTC blocks as
// stored: what a GPU that samples ASTC holds; one that cannot holds their RGBA8 decoding, 4 to 16
// times more), float RGB for the environment image (before it is reduced
// to the environment's size). An image whose header cannot be read is left to its decoder, which
// reports it. False with *error listing the largest images when the sum exceeds
// kMaxSceneImageBytes.
bool checkSceneImageBudget(const Scene& scene, std::string* error);

}  // namespace facet::runtime
