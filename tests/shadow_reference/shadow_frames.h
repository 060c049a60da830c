// Frames of the shadow pass (Vulkan or GL) scored against the ray-cast reference (docs/shadows.md,
// "Visibility from the renderer"): a scene lit by the sun alone is rendered with and without its
// pass, the ratio of the two frames is the rendered visibility, and the reference is ray-cast for
// the same pixels. Shared by test_vulkan_shadows (the pass per tier on both backends) and
// test_vulkan_shadow_cases (the hard cases and the bias sweep).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "facet/abi/shader_abi.h"
#include "facet/runtime/render_backend.h"
#include "facet/shadow_reference/reference_image.h"
#include "facet/shadow_reference/shadow_score.h"

namespace facet::runtime::shadow_frames {

// The packages every material of these scenes uses: `plastic`, a grey lit material, with the
// receivers of 1, 2 and 4 cascades and the depth-only programs.
const std::string& packages();

enum class Api { Vulkan, Gl };

const char* apiName(Api api);

// Vulkan with validation layers (a validation error fails the test), or GL on its headless
// context (GLES 3.2 on EGL where there is one, else OSMesa) with its debug output checked alike.
std::unique_ptr<RenderBackend> makeBackend(Api api);

// The scene's frame rendered by `backend` (empty after a failed EXPECT). `shadow`, when given,
// receives the uniforms the receivers read (zeros without a pass).
FrameResult render(RenderBackend& backend, const std::string& json, const std::string& name,
                   abi::ShadowUniforms* shadow = nullptr);

// The scene's ray-cast reference over a footprint of `footprint` metres (empty on failure).
shadow_reference::ReferenceImage referenceOf(const std::string& json, const std::string& name, double footprint);

// The scene as text with the sun's castShadows set.
std::string withSunCasting(const std::string& json, bool casts);

// A scene of tests/data/scenes/shadows/ made measurable: lit by the sun alone (sky luminance 0)
// and every object `plastic`.
std::string sunOnlyScene(const std::string& fileName);

// The frame's LDR as a PNG in the test's scratch folder; its path, or "" after a failed EXPECT.
std::string renderToPng(RenderBackend& backend, const std::string& json, const std::string& name,
                        abi::ShadowUniforms* shadow = nullptr);

struct Measured {
  shadow_reference::ReferenceImage reference;
  shadow_reference::RenderedVisibility rendered;
  shadow_reference::ShadowScore score;
  std::vector<glm::dvec3> points;  // each pixel's surface point (NaN where the camera ray meets nothing)
  abi::ShadowUniforms shadow{};    // what the shadowed frame's receivers read
  glm::dvec3 cameraPosition{0};
};

// The scene rendered on `api` with and without its shadow pass, and the reference over a
// footprint of `footprint` metres.
Measured measure(const std::string& json, const std::string& name, double footprint, Api api = Api::Vulkan);

// Mean rendered visibility over the measurable surface pixels whose footprint is all `visible`.
double meanVisibility(const Measured& m, float visible, size_t* count);

// The cascade a receiver at world point `p` reads (chunks/shadow_cascade.glsl: the first whose
// split lies beyond its view depth), and that cascade's texel size in metres.
double viewDepth(const Measured& m, const glm::dvec3& p);
int cascadeAt(const Measured& m, const glm::dvec3& p);
double texelSizeAt(const Measured& m, const glm::dvec3& p);

// The score over the pixels `keep` accepts (by index) only: the others are left out as sky.
shadow_reference::ShadowScore scoreWhere(const Measured& m, const std::function<bool(size_t)>& keep);

}  // namespace facet::runtime::shadow_frames
