// The scene JSON the viewer renders (and, later, the manifest matc reads to build only the
// variants a scene needs). Format: docs/scene-format.md.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "facet/scene/post_settings.h"
#include "facet/scene/texture_sampler.h"

// The scene library's folder, the runtime's namespace: these types are the runtime's description
// of a frame (environment.h and scene_frame.h take them), apps built against an installed Facet
// name them facet::runtime::Scene, Camera, ..., and renaming them would change every such app
// and most of the runtime with no change of meaning. The reader's own tools (json_document.h,
// asset_path.h) are in facet::scene.
namespace facet::runtime {

struct Camera {
  glm::dvec3 position{0, 0, 4};
  glm::dvec3 target{0, 0, 0};
  glm::dvec3 up{0, 1, 0};
  double fovYDegrees = 40;
  double nearPlane = 0.1;
  double farPlane = 100;
  // Physical settings: they give the exposure that pre-exposes every light.
  double aperture = 16;  // f-number
  double shutterSeconds = 1.0 / 125;
  double iso = 100;
};

struct Sun {
  glm::dvec3 direction{0, -1, 0};  // the direction the light travels (from the sun to the scene)
  double illuminance = 110000;     // lux, on a surface facing the sun
  glm::dvec3 color{1, 1, 1};       // linear, multiplies illuminance
  bool castShadows = false;        // receivers in the scene take the sun's shadow map (docs/shadows.md)
};

// The largest shadow atlas a scene may ask for, texels per side.
inline constexpr uint32_t kMaxShadowAtlasSize = 8192;

// Where the casters' slope-scaled bias is added (docs/shadows.md, "Bias"): by the rasteriser
// (its slope factor), or by the depth-only program's vertex stage from the normal's angle to the
// light (Guo and Li, "Practical High-Performance Rendering on Mobile Platforms", 2023), which
// needs the `<tier>.depth.slope` programs.
enum class SlopeBiasStage { Raster, Vertex };

// The sun's shadow map (docs/shadows.md): every cascade a viewport rectangle of one square depth
// atlas. Biases are in shadow texels of the cascade they apply to, so one setting holds for every
// cascade and atlas size.
struct ShadowSettings {
  uint32_t atlasSize = 2048;  // texels per side, a power of two in [256, 8192] (and the device's limit)
  uint32_t cascades = 4;      // 1..4; 3 uses the 4-cascade receiver variant
  double distance = 60;       // metres from the camera at which the shadow has faded out
  double splitLambda = 0.75;  // 0: uniform splits, 1: logarithmic (the practical split scheme)
  double depthBias = 1.0;     // constant depth bias, in texels
  double slopeBias = 2.0;     // depth bias per unit of depth slope, in texels
  double normalBias = 1.0;    // lookup offset along the surface normal, in texels
  SlopeBiasStage slopeStage = SlopeBiasStage::Raster;
};

// A punctual light: a point light radiating equally in all directions, or a spot light
// restricted to a cone (Filament's punctual-light model; docs/lighting-units.md).
struct PunctualLight {
  bool spot = false;
  glm::dvec3 position{0, 0, 0};
  double intensity = 100;          // candela (lumen per steradian)
  glm::dvec3 color{1, 1, 1};       // linear, multiplies intensity
  double range = 10;               // metres: the light fades smoothly to 0 at this distance
  glm::dvec3 direction{0, -1, 0};  // spot: the cone's axis, the direction the light travels
  double innerAngleDegrees = 20;   // spot: full intensity inside this half-angle
  double outerAngleDegrees = 30;   // spot: no light outside this half-angle
  bool castShadows = false;        // spot only, at most kMaxShadowSpotLights of them (docs/shadows.md, "Spot shadows")
};

// Spot lights that may cast in one scene: each costs a rectangle of the atlas, a pass over its
// casters and a filtered lookup per receiving pixel (docs/shadows.md, "Spot shadows").
inline constexpr size_t kMaxShadowSpotLights = 1;
// The widest cone a spot light may cast from (its outerAngle, degrees): its shadow is one
// perspective view, whose texels at the cone's edge cover 1 / cos³ of those on its axis on a sphere
// around the light (8× at 60°), and which cannot reach 90°.
inline constexpr double kMaxShadowSpotAngleDegrees = 60;

// Punctual lights per scene: the shaders have fixed-count permutations up to this many
// (permutations::kMaxPointLights).
inline constexpr size_t kMaxSceneLights = 4;

// The meshes the runtime builds itself (runtime/mesh.h): a scene object's `mesh` is one of these
// or a glTF file.
inline constexpr const char* kBuiltinMeshes[] = {"sphere", "plane", "box"};

// An object is placed by model = translate(position) · rotate(rotation) · scale(radius · scale):
// scaled about its origin, then rotated, then moved (docs/scene-format.md, "Transforms").
struct SceneObject {
  std::string mesh = "sphere";  // a kBuiltinMeshes name, or a .gltf/.glb path (resolved, inside the scene's folder)
  std::string material;         // package name: <package dir>/<material>.matpkg
  // With a glTF mesh: draw only the primitives whose glTF material is this index (-1: those
  // without one), so that each glTF material is drawn with its own Facet material (docs/gltf.md).
  std::optional<int> gltfMaterial;
  glm::dvec3 position{0, 0, 0};
  glm::dquat rotation{1, 0, 0, 0};  // unit length (w, x, y, z in glm's constructor)
  double radius = 1;                // a uniform scale: the unit sphere's radius
  glm::dvec3 scale{1, 1, 1};        // per axis, each > 0; multiplies radius (a scene gives one of the two)
  bool castShadows = true;          // drawn into the shadow atlas (transparent materials never are)
  bool receiveShadows = true;       // shaded with the receiver variant when the scene casts
  std::map<std::string, std::vector<double>> params;
  std::set<std::string>
      boolParams;  // params given as JSON true/false (1/0 in `params`): only a bool parameter takes one
  std::map<std::string, std::string>
      textures;  // texture parameter -> image path (relative to the scene file, resolved)
  std::map<std::string, TextureSampler>
      samplers;  // texture parameter -> how it is sampled (default: repeat, trilinear)
};

// The object's model matrix, T · R · S (the scene's `position`, `rotation`, `radius` · `scale`).
glm::dmat4 modelMatrix(const SceneObject& o);

// The environment that lights a scene by image-based lighting (docs/scene-format.md,
// "environment"). Radiance = luminance × the image's (or the sky's) relative value, in cd/m².
struct Environment {
  std::string image;        // equirect image path (resolved); empty: the analytic sky below
  double luminance = 1000;  // cd/m² that a value of 1 in the image or sky colours stands for
  // Analytic sky (evaluated into an equirect image on the CPU): mix(horizon, zenith, √y) above the
  // horizon, mix(horizon, ground, √−y) below it, y the direction's up component.
  glm::dvec3 zenith{0.25, 0.45, 1.0};
  glm::dvec3 horizon{1.0, 1.0, 1.0};
  glm::dvec3 ground{0.3, 0.25, 0.2};
};

// "background" (docs/scene-format.md): what shows where no object covers a pixel.
inline constexpr double kMaxBackgroundLod = 4;  // the prefiltered environment's last level
struct Background {
  // The environment drawn behind everything (runtime/background.h), at level `lod`, its radiance ×
  // `intensity`; false: the environment's mean radiance as a flat colour (exact for a constant
  // `sky`). Default: drawn when the scene has an `environment`.
  bool environment = false;
  double lod = 0;
  double intensity = 1;
};

struct Scene {
  uint32_t width = 256;
  uint32_t height = 256;
  std::string tier = "high";
  Camera camera;
  std::optional<Sun> sun;
  std::vector<PunctualLight> lights;
  ShadowSettings shadows;   // the "shadows" block; used when sun->castShadows
  double skyLuminance = 0;  // cd/m², a constant environment (used when `environment` is absent)
  std::optional<Environment> environment;
  Background background;
  std::vector<SceneObject> objects;
  PostSettings post;  // the post pass's effects (docs/scene-format.md "post")
  // Their settings, read when post.colorGrading / post.vignette are on: grading from settings, or
  // from a .cube file (resolved, under the asset root) when gradingLut is not empty.
  ColorGradingSettings grading;
  std::string gradingLut;
  VignetteSettings vignette;
  BloomSettings bloom;       // read when post.bloom is on
  uint32_t msaaSamples = 1;  // "antialiasing": {"msaa": 1 | 2 | 4}: the forward pass's samples per pixel
  bool fxaa = false;         // "antialiasing": {"fxaa": true}: an FXAA pass after the post pass
  // "renderScale": 0.5..1, the forward pass's size / the output's (render_path.h)
  double renderScale = 1.0;
  // The real folder the scene's files were confined to (SceneReadOptions), which also confines
  // what its glTF files read; "" for a Scene built in code.
  std::string assetRoot;
};

// Which files a scene may name (texture and environment images, glTF meshes). By default only
// those under the scene file's folder, so that a scene from elsewhere cannot make the app read
// (and, through a rendered image, reveal) other files of the machine: `../`, absolute paths and
// symbolic links that lead out of the folder are errors. An app that trusts its scenes widens it
// (facet-view --asset-root).
struct SceneReadOptions {
  std::string assetRoot;  // "": the scene file's folder
};

// The number of sun cascades a scene renders: 0 when nothing casts (no sun, or the sun's
// castShadows off), else shadows.cascades.
uint32_t sunShadowCascades(const Scene& s);
// The indices into s.lights of the spot lights that cast, in slot order (at most kMaxShadowSpotLights).
// Inline: the runtime's core, which links no scene reader, fits their shadows.
inline std::vector<size_t> shadowSpotLights(const Scene& s) {
  std::vector<size_t> casting;
  for (size_t i = 0; i < s.lights.size(); ++i)
    if (s.lights[i].spot && s.lights[i].castShadows) casting.push_back(i);
  return casting;
}

// The camera's projection × view in double precision: what the renderer uploads (as float) and
// what a CPU reference of the same image must use to cast the same rays.
glm::dmat4 viewProjection(const Scene& s);

// Parses scene JSON. Errors read `<path>:<line>:<col>: error: ...` for syntax errors and
// `<path>: error: <json pointer>: ...` for wrong values.
std::optional<Scene> parseScene(const std::string& path, const std::string& text, std::string* error,
                                const SceneReadOptions& options = {});
std::optional<Scene> loadScene(const std::string& path, std::string* error, const SceneReadOptions& options = {});
// The text of a scene file, as loadScene reads it: a regular file of at most 16 MiB.
std::optional<std::string> readSceneFile(const std::string& path, std::string* error);

}  // namespace facet::runtime
