// facet-view --shadow-cascades: the pixels of shadow receivers tinted by the cascade of the sun's
// shadow they read, for debugging cascade splits. A viewer-only overlay on the rendered LDR image:
// each pixel's surface is found by ray-casting the scene on the CPU (facet_shadow_reference, the
// renderer's camera and meshes) and its view depth picks the cascade as the receiver shaders do
// (chunks/shadow_cascade.glsl), so no shipped shader variant carries a debug path.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "facet/abi/shader_abi.h"
#include "facet/scene/scene.h"

namespace facet::viewer {

// Tints `rgba` (the scene's width × height, rows top to bottom) halfway to red, green, blue and
// yellow for cascades 0..3 where a receiving object is seen nearer than the shadow distance;
// `pixels` counts them per cascade. False with *error when the scene's meshes cannot be built.
bool tintShadowCascades(const runtime::Scene& scene, const abi::ShadowUniforms& shadow, std::vector<uint8_t>* rgba,
                        std::array<size_t, abi::kMaxShadowCascades>* pixels, std::string* error);

}  // namespace facet::viewer
