// Frames of the shadow pass (Vulkan or GL) scored against the ray-cast reference (docs/shadows.md,
// "Visibility from the renderer"): a scene lit by the sun alone (or by one spot light alone) is
// rendered with and without its pass, the ratio of the two frames is the rendered visibility, and the reference is
// ray-cast for the same pixels. Shared by test_vulkan_shadows (the pass per tier on both backends) and
// test_vulkan_shadow_cases (the hard cases and the bias sweep).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "facet/abi/shader_abi.h"
#include "facet/runtime/render_backend.h"
#include "facet/shadow_reference/reference_image.h"
#include "facet/shadow_reference/shadow_score.h"

namespace facet::runtime::shadow_frames {

// The packages every material of these scenes uses: `plastic`, a grey lit material, with the
// receivers of 1, 2 and 4 cascades and the depth-only programs.
const std::string& packages();
// The same material with one point/spot light, as a receiver of its spot shadow (`.sp1`) and not,
// without a sun's receivers, and the depth-only programs: what spot-lit scenes ask for.
const std::string& spotPackages();

// Which light's shadow a scene is measured for: the sun's (kSun), or the spot light /lights/N's.
inline constexpr int kSun = -1;

enum class Api { Vulkan, Gl };

const char* apiName(Api api);

// Vulkan with validation layers (a validation error fails the test), or GL on its headless
// context (GLES 3.2 on EGL where there is one, else OSMesa) with its debug output checked alike.
std::unique_ptr<RenderBackend> makeBackend(Api api);

// The scene's frame rendered by `backend` (empty after a failed EXPECT) from packages() (a scene
// lit by a spot light: spotPackages()). `shadow`, when given, receives the uniforms the receivers
// read (zeros without a pass).
FrameResult render(RenderBackend& backend, const std::string& json, const std::string& name,
                   abi::ShadowUniforms* shadow = nullptr);

// The scene's ray-cast reference over a footprint of `footprint` metres for the sun, or the spot
// light /lights/`light` (empty on failure).
shadow_reference::ReferenceImage referenceOf(const std::string& json, const std::string& name, double footprint,
                                             int light = kSun);

// The scene as text with the sun's castShadows set.
std::string withSunCasting(const std::string& json, bool casts);
// The scene as text with the castShadows of `light` (the sun, or /lights/N) set.
std::string withCasting(const std::string& json, int light, bool casts);

// A scene of tests/data/scenes/shadows/ made measurable: no sky light (luminance 0), so lit by its
// sun or spot alone, and every object `plastic`.
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
  glm::dmat4 viewProjection{1.0};  // the camera's, world → GL clip
};

// The scene rendered on `api` with and without the shadow of `light` (the sun, or /lights/N: a spot
// light, the scene's only light), and the reference over a footprint of `footprint` metres.
Measured measure(const std::string& json, const std::string& name, double footprint, Api api = Api::Vulkan,
                 int light = kSun);
// The same on a backend of `api` the caller keeps over several frames.
Measured measure(RenderBackend& backend, Api api, const std::string& json, const std::string& name, double footprint,
                 int light = kSun);

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
