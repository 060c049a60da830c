#include "facet/scene/scene.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

#include "facet/package/package.h"
#include "facet/scene/asset_path.h"
#include "facet/scene/json_document.h"

namespace facet::runtime {
namespace {

using nlohmann::json;

// A wrong value in the scene: thrown inside this file only, turned into an error message.
struct SceneError {
  std::string pointer;
  std::string message;
};

[[noreturn]] void fail(const std::string& pointer, std::string message) {
  throw SceneError{pointer, std::move(message)};
}

// Rejects keys this reader does not know: a typo ("ilumination") must not silently fall back
// to a default.
void onlyKeys(const json& object, const std::string& pointer, std::initializer_list<const char*> keys) {
  if (!object.is_object()) fail(pointer, "expected an object");
  for (const auto& [key, value] : object.items()) {
    bool known = false;
    for (const char* k : keys) known = known || key == k;
    if (!known) fail(pointer + "/" + scene::pointerSegment(key), "unknown key '" + scene::pointerSegment(key) + "'");
  }
}

double number(const json& j, const std::string& pointer, double lo, double hi) {
  if (!j.is_number()) fail(pointer, "expected a number");
  double v = j.get<double>();
  if (!std::isfinite(v) || v < lo || v > hi)
    fail(pointer, "value " + j.dump() + " is outside [" + json(lo).dump() + ", " + json(hi).dump() + "]");
  return v;
}

// Sizes and counts: 256.7 pixels is a mistake, not 256.
uint32_t wholeNumber(const json& j, const std::string& pointer, double lo, double hi) {
  double v = number(j, pointer, lo, hi);
  if (v != std::floor(v)) fail(pointer, "expected a whole number, not " + j.dump());
  return uint32_t(v);
}

// Resolves the file paths a scene names (images, glTF meshes): relative to the scene's folder, and only under the
// asset root (SceneReadOptions). Containment is decided on the real paths (facet/scene/asset_path.h:
// symbolic links followed, dangling ones too), so a link inside the folder cannot point out of it.
class AssetPaths {
 public:
  AssetPaths(std::filesystem::path sceneDir, const std::string& assetRoot)
      : sceneDir_(std::move(sceneDir)),
        root_(scene::realPath(assetRoot.empty() ? sceneDir_ : std::filesystem::path(assetRoot))) {}

  std::string resolve(const json& j, const std::string& pointer) const {
    if (!j.is_string()) fail(pointer, "expected a file path");
    const std::string given = j.get<std::string>();
    if (given.empty() || given.find('\0') != std::string::npos) fail(pointer, "expected a file path");
    const std::filesystem::path path = (sceneDir_ / given).lexically_normal();
    if (!scene::isInside(root_, scene::realPath(path)))
      fail(pointer, "'" + scene::shownValue(given) + "' is outside the folder this scene may read files from (" +
                        root_.string() + "); an app that trusts the scene can allow another (facet-view --asset-root)");
    return path.string();
  }

  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path sceneDir_;
  std::filesystem::path root_;
};

glm::dvec3 vec3(const json& j, const std::string& pointer) {
  if (!j.is_array() || j.size() != 3) fail(pointer, "expected an array of 3 numbers");
  return {number(j[0], pointer + "/0", -1e6, 1e6), number(j[1], pointer + "/1", -1e6, 1e6),
          number(j[2], pointer + "/2", -1e6, 1e6)};
}

// Directions are normalised by the renderer: a vector too short to normalise in single
// precision (1e-300, or 0) would become NaN and leave the image empty or unlit.
constexpr double kMinDirectionLength = 1e-6;

glm::dvec3 direction(const json& j, const std::string& pointer) {
  glm::dvec3 d = vec3(j, pointer);
  if (glm::length(d) < kMinDirectionLength) fail(pointer, "a direction needs a length of at least 1e-6");
  return d;
}

bool boolean(const json& j, const std::string& pointer) {
  if (!j.is_boolean()) fail(pointer, "expected true or false");
  return j.get<bool>();
}

std::string string(const json& j, const std::string& pointer) {
  if (!j.is_string()) fail(pointer, "expected a string");
  return j.get<std::string>();
}

glm::dvec3 colour(const json& j, const std::string& pointer) {
  glm::dvec3 c = vec3(j, pointer);
  for (int i = 0; i < 3; ++i)
    if (c[i] < 0 || c[i] > 1e3) fail(pointer + "/" + std::to_string(i), "a colour component must lie in [0, 1000]");
  return c;
}

Camera camera(const json& j) {
  onlyKeys(j, "/camera", {"position", "target", "up", "fovY", "near", "far", "aperture", "shutter", "iso"});
  Camera c;
  if (j.contains("position")) c.position = vec3(j["position"], "/camera/position");
  if (j.contains("target")) c.target = vec3(j["target"], "/camera/target");
  if (j.contains("up")) c.up = direction(j["up"], "/camera/up");
  if (j.contains("fovY")) c.fovYDegrees = number(j["fovY"], "/camera/fovY", 1, 179);
  if (j.contains("near")) c.nearPlane = number(j["near"], "/camera/near", 1e-4, 1e6);
  if (j.contains("far")) c.farPlane = number(j["far"], "/camera/far", 1e-3, 1e7);
  if (j.contains("aperture")) c.aperture = number(j["aperture"], "/camera/aperture", 0.5, 64);
  if (j.contains("shutter")) c.shutterSeconds = number(j["shutter"], "/camera/shutter", 1e-5, 60);
  if (j.contains("iso")) c.iso = number(j["iso"], "/camera/iso", 1, 1e6);
  if (c.farPlane <= c.nearPlane) fail("/camera/far", "must be greater than near");
  glm::dvec3 view = c.target - c.position;
  if (glm::length(view) < kMinDirectionLength)
    fail("/camera/target", "must lie at least 1e-6 from the camera position");
  // The view basis is built from cross(view, up): parallel vectors leave it undefined.
  if (glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-3)
    fail("/camera/up", "must not be parallel to the view direction (target − position)");
  return c;
}

Sun sun(const json& j) {
  onlyKeys(j, "/sun", {"direction", "illuminance", "color", "castShadows"});
  Sun s;
  if (j.contains("castShadows")) s.castShadows = boolean(j["castShadows"], "/sun/castShadows");
  if (j.contains("direction")) s.direction = direction(j["direction"], "/sun/direction");
  if (j.contains("illuminance")) s.illuminance = number(j["illuminance"], "/sun/illuminance", 0, 1e6);
  if (j.contains("color")) s.color = colour(j["color"], "/sun/color");
  return s;
}

PunctualLight light(const json& j, const std::string& pointer) {
  onlyKeys(j, pointer,
           {"type", "position", "intensity", "color", "range", "direction", "innerAngle", "outerAngle", "castShadows"});
  PunctualLight l;
  std::string type = j.contains("type") ? string(j["type"], pointer + "/type") : "";
  if (type != "point" && type != "spot") fail(pointer + "/type", "expected \"point\" or \"spot\"");
  l.spot = type == "spot";
  // A point light would need six faces of casters (docs/shadows.md, "Status"): a light asking for
  // a shadow it would not get is an error, not an unshadowed image.
  if (j.contains("castShadows")) {
    l.castShadows = boolean(j["castShadows"], pointer + "/castShadows");
    if (l.castShadows && !l.spot)
      fail(pointer + "/castShadows",
           "point-light shadows are not supported; only the sun and spot lights cast shadows");
  }
  if (!l.spot)
    for (const char* key : {"direction", "innerAngle", "outerAngle"})
      if (j.contains(key)) fail(pointer + "/" + key, "only a spot light has a " + std::string(key));
  if (j.contains("position")) l.position = vec3(j["position"], pointer + "/position");
  if (j.contains("intensity")) l.intensity = number(j["intensity"], pointer + "/intensity", 0, 1e7);
  if (j.contains("color")) l.color = colour(j["color"], pointer + "/color");
  if (j.contains("range")) l.range = number(j["range"], pointer + "/range", 0.01, 1e4);
  if (j.contains("direction")) l.direction = direction(j["direction"], pointer + "/direction");
  if (j.contains("innerAngle")) l.innerAngleDegrees = number(j["innerAngle"], pointer + "/innerAngle", 0, 90);
  if (j.contains("outerAngle")) l.outerAngleDegrees = number(j["outerAngle"], pointer + "/outerAngle", 0.5, 90);
  if (l.innerAngleDegrees >= l.outerAngleDegrees) fail(pointer + "/innerAngle", "must be smaller than outerAngle");
  if (l.castShadows && l.outerAngleDegrees > kMaxShadowSpotAngleDegrees)
    fail(pointer + "/outerAngle", "a spot light casting shadows has an outerAngle of at most " +
                                      std::to_string(int(kMaxShadowSpotAngleDegrees)) +
                                      " degrees (one perspective view)");
  return l;
}

Environment environment(const json& j, const AssetPaths& assets) {
  onlyKeys(j, "/environment", {"image", "sky", "luminance"});
  Environment e;
  if (j.contains("image") == j.contains("sky")) fail("/environment", "expected exactly one of 'image' and 'sky'");
  if (j.contains("image")) e.image = assets.resolve(j["image"], "/environment/image");
  if (j.contains("luminance")) e.luminance = number(j["luminance"], "/environment/luminance", 0, 1e6);
  if (j.contains("sky")) {
    const json& sky = j["sky"];
    onlyKeys(sky, "/environment/sky", {"zenith", "horizon", "ground", "luminance"});
    if (sky.contains("luminance")) {
      if (j.contains("luminance")) fail("/environment/sky/luminance", "give the luminance once");
      e.luminance = number(sky["luminance"], "/environment/sky/luminance", 0, 1e6);
    }
    if (sky.contains("zenith")) e.zenith = colour(sky["zenith"], "/environment/sky/zenith");
    if (sky.contains("horizon")) e.horizon = colour(sky["horizon"], "/environment/sky/horizon");
    if (sky.contains("ground")) e.ground = colour(sky["ground"], "/environment/sky/ground");
  }
  return e;
}

// Euler angles as people write them by hand: degrees, about the world's x, y and z axes, applied
// in that order (R = Rz · Ry · Rx, Blender's "XYZ Euler"), each counter-clockwise looking down its
// axis towards the origin (right-hand rule). One angle is the common case (a wall turned by 30°
// about y), and a fixed order of fixed axes is the one thing a reader must know for several.
glm::dquat eulerDegrees(const json& j, const std::string& pointer) {
  if (!j.is_array() || j.size() != 3)
    fail(pointer,
         "expected [x, y, z]: angles in degrees about the x, y and z axes (a quaternion goes in 'quaternion')");
  glm::dvec3 a;
  for (int i = 0; i < 3; ++i) a[i] = glm::radians(number(j[size_t(i)], pointer + "/" + std::to_string(i), -360, 360));
  return glm::angleAxis(a.z, glm::dvec3(0, 0, 1)) * glm::angleAxis(a.y, glm::dvec3(0, 1, 0)) *
         glm::angleAxis(a.x, glm::dvec3(1, 0, 0));
}

// A quaternion in glTF's order, [x, y, z, w], normalised here (so [0, 1, 0, 1] is 90° about y).
// One too short to normalise has no rotation to give.
glm::dquat quaternion(const json& j, const std::string& pointer) {
  if (!j.is_array() || j.size() != 4) fail(pointer, "expected [x, y, z, w]: a quaternion");
  double c[4];
  for (int i = 0; i < 4; ++i) c[i] = number(j[size_t(i)], pointer + "/" + std::to_string(i), -1e6, 1e6);
  const glm::dquat q(c[3], c[0], c[1], c[2]);  // glm's constructor takes w first
  const double length = glm::length(q);
  if (length < kMinDirectionLength) fail(pointer, "a quaternion needs a length of at least 1e-6 to be normalised");
  return q / length;
}

// A scale per axis. Zero flattens the object (its normal matrix has no inverse). A negative one
// mirrors it, which would turn its triangles' winding and tangent frames inside out; Facet refuses
// it rather than draw the object's back faces: the built-in meshes are symmetric (a rotation gives
// the same shape) and a glTF file mirrors in its own node transforms (runtime/gltf_mesh.h).
glm::dvec3 scale(const json& j, const std::string& pointer) {
  const auto component = [&](const json& c, const std::string& p) {
    if (c.is_number() && c.get<double>() == 0) fail(p, "a scale of 0 flattens the object; give a scale > 0");
    if (c.is_number() && c.get<double>() < 0)
      fail(p,
           "a negative scale (" + c.dump() + ") would mirror the object; mirroring is not supported, give a scale > 0");
    return number(c, p, 1e-4, 1e6);
  };
  if (j.is_number()) return glm::dvec3(component(j, pointer));
  if (!j.is_array() || j.size() != 3) fail(pointer, "expected a number or [x, y, z]");
  return {component(j[0], pointer + "/0"), component(j[1], pointer + "/1"), component(j[2], pointer + "/2")};
}

std::string builtinMeshNames() {
  std::string names;
  for (const char* name : kBuiltinMeshes) names += std::string(names.empty() ? "" : ", ") + name;
  return names;
}

// One of `names`, given as its index; the error lists them.
template <size_t N>
size_t oneOf(const json& j, const std::string& pointer, const char* const (&names)[N]) {
  const std::string v = string(j, pointer);
  for (size_t i = 0; i < N; ++i)
    if (v == names[i]) return i;
  std::string list;
  for (const char* name : names) list += std::string(list.empty() ? "" : ", ") + name;
  fail(pointer, "'" + scene::pointerSegment(v) + "' is not one of " + list);
}

// A texture parameter's sampler: glTF 2.0's wrap modes and filters by their names in camel case.
TextureSampler sampler(const json& j, const std::string& pointer) {
  onlyKeys(j, pointer, {"wrapS", "wrapT", "magFilter", "minFilter"});
  constexpr const char* kWraps[] = {"repeat", "clampToEdge", "mirroredRepeat"};
  constexpr const char* kMagFilters[] = {"nearest", "linear"};
  constexpr const char* kMinFilters[] = {
      "nearest", "linear", "nearestMipmapNearest", "linearMipmapNearest", "nearestMipmapLinear", "linearMipmapLinear"};
  TextureSampler s;
  if (j.contains("wrapS")) s.wrapS = TextureWrap(oneOf(j["wrapS"], pointer + "/wrapS", kWraps));
  if (j.contains("wrapT")) s.wrapT = TextureWrap(oneOf(j["wrapT"], pointer + "/wrapT", kWraps));
  if (j.contains("magFilter")) s.magLinear = oneOf(j["magFilter"], pointer + "/magFilter", kMagFilters) == 1;
  if (j.contains("minFilter")) {
    const size_t min = oneOf(j["minFilter"], pointer + "/minFilter", kMinFilters);
    s.minLinear = min % 2 == 1;
    s.mipmaps = min >= 2;
    s.mipLinear = min >= 4;
  }
  return s;
}

SceneObject object(const json& j, const std::string& pointer, const AssetPaths& assets) {
  onlyKeys(j, pointer,
           {"mesh", "gltfMaterial", "material", "position", "rotation", "quaternion", "radius", "scale", "castShadows",
            "receiveShadows", "params", "samplers"});
  SceneObject o;
  if (j.contains("castShadows")) o.castShadows = boolean(j["castShadows"], pointer + "/castShadows");
  if (j.contains("receiveShadows")) o.receiveShadows = boolean(j["receiveShadows"], pointer + "/receiveShadows");
  if (j.contains("mesh")) o.mesh = string(j["mesh"], pointer + "/mesh");
  if (std::find(std::begin(kBuiltinMeshes), std::end(kBuiltinMeshes), o.mesh) == std::end(kBuiltinMeshes)) {
    // A glTF 2.0 file, relative to the scene's folder and inside the asset root, as images are
    // (runtime/gltf_mesh.h).
    const std::string extension = std::filesystem::path(o.mesh).extension().string();
    if (extension != ".gltf" && extension != ".glb")
      fail(pointer + "/mesh", "unknown mesh '" + scene::pointerSegment(o.mesh) + "' (built in: " + builtinMeshNames() +
                                  "; or a .gltf/.glb file)");
    o.mesh = assets.resolve(j["mesh"], pointer + "/mesh");
  }
  if (j.contains("gltfMaterial")) {
    if (std::find(std::begin(kBuiltinMeshes), std::end(kBuiltinMeshes), o.mesh) != std::end(kBuiltinMeshes))
      fail(pointer + "/gltfMaterial", "only a glTF mesh has materials to choose from");
    // glTF indices are JSON integers; 2^20 materials is far beyond any file the budgets admit.
    const double index = number(j["gltfMaterial"], pointer + "/gltfMaterial", -1, double(1 << 20));
    if (index != std::floor(index)) fail(pointer + "/gltfMaterial", "expected a material index (an integer, or -1)");
    o.gltfMaterial = int(index);
  }
  if (!j.contains("material")) fail(pointer, "missing 'material'");
  o.material = string(j["material"], pointer + "/material");
  // A material name is an identifier of the language (what `material NAME {` accepts): no path,
  // no NUL to cut the file name short, nothing that could open another file.
  if (!package::isValidName(o.material))
    fail(pointer + "/material",
         "expected a material name (letters, digits, _), not '" + scene::pointerSegment(o.material) + "'");
  if (j.contains("position")) o.position = vec3(j["position"], pointer + "/position");
  if (j.contains("rotation") && j.contains("quaternion"))
    fail(pointer + "/quaternion", "give either 'rotation' (degrees) or 'quaternion', not both");
  if (j.contains("rotation")) o.rotation = eulerDegrees(j["rotation"], pointer + "/rotation");
  if (j.contains("quaternion")) o.rotation = quaternion(j["quaternion"], pointer + "/quaternion");
  // Two sizes for one object would leave the reader guessing whether they multiply.
  if (j.contains("radius") && j.contains("scale"))
    fail(pointer + "/scale", "give either 'radius' (a uniform scale) or 'scale', not both");
  if (j.contains("radius")) o.radius = number(j["radius"], pointer + "/radius", 1e-4, 1e6);
  if (j.contains("scale")) o.scale = scale(j["scale"], pointer + "/scale");
  if (j.contains("params")) {
    const json& params = j["params"];
    if (!params.is_object()) fail(pointer + "/params", "expected an object");
    for (const auto& [name, value] : params.items()) {
      std::string p = pointer + "/params/" + scene::pointerSegment(name);
      if (!package::isValidName(name)) fail(p, "expected a parameter name (letters, digits, _)");
      std::vector<double> v;
      if (value.is_string()) {  // a texture parameter's image, relative to the scene file
        o.textures[name] = assets.resolve(value, p);
        continue;
      }
      if (value.is_number())
        v.push_back(number(value, p, -1e30, 1e30));
      else if (value.is_boolean()) {
        v.push_back(value.get<bool>() ? 1 : 0);
        o.boolParams.insert(name);  // checked against the parameter's type when the package is known
      } else if (value.is_array() && !value.empty() && value.size() <= 4)
        for (size_t i = 0; i < value.size(); ++i)
          v.push_back(number(value[i], p + "/" + std::to_string(i), -1e30, 1e30));
      else
        fail(p, "expected a number, a bool, an array of 1 to 4 numbers, or an image path");
      o.params[name] = std::move(v);
    }
  }
  if (j.contains("samplers")) {
    const json& samplers = j["samplers"];
    if (!samplers.is_object()) fail(pointer + "/samplers", "expected an object");
    for (const auto& [name, value] : samplers.items()) {
      const std::string p = pointer + "/samplers/" + scene::pointerSegment(name);
      if (!package::isValidName(name)) fail(p, "expected a texture parameter name (letters, digits, _)");
      o.samplers[name] = sampler(value, p);  // that it names a texture parameter is checked with the package
    }
  }
  return o;
}

std::array<double, 3> perChannel(const json& j, const std::string& pointer, double lo, double hi) {
  if (!j.is_array() || j.size() != 3) fail(pointer, "expected an array of 3 numbers (red, green, blue)");
  return {number(j[0], pointer + "/0", lo, hi), number(j[1], pointer + "/1", lo, hi),
          number(j[2], pointer + "/2", lo, hi)};
}

// Colour grading: settings, or a .cube file instead (one LUT either way; mixing them would leave
// the reader guessing the order).
void grading(const json& j, const AssetPaths& assets, Scene* s) {
  onlyKeys(j, "/post/grading", {"temperature", "tint", "contrast", "saturation", "lift", "gamma", "gain", "lut"});
  ColorGradingSettings& g = s->grading;
  if (j.contains("lut")) {
    if (j.size() != 1) fail("/post/grading/lut", "give either a .cube file or grading settings, not both");
    s->gradingLut = assets.resolve(j["lut"], "/post/grading/lut");
  }
  if (j.contains("temperature")) g.temperature = number(j["temperature"], "/post/grading/temperature", -1, 1);
  if (j.contains("tint")) g.tint = number(j["tint"], "/post/grading/tint", -1, 1);
  if (j.contains("contrast")) g.contrast = number(j["contrast"], "/post/grading/contrast", 0.1, 4);
  if (j.contains("saturation")) g.saturation = number(j["saturation"], "/post/grading/saturation", 0, 4);
  if (j.contains("lift")) g.lift = perChannel(j["lift"], "/post/grading/lift", -1, 1);
  if (j.contains("gamma")) g.gamma = perChannel(j["gamma"], "/post/grading/gamma", 0.1, 10);
  if (j.contains("gain")) g.gain = perChannel(j["gain"], "/post/grading/gain", 0, 10);
}

void vignette(const json& j, VignetteSettings* v) {
  onlyKeys(j, "/post/vignette", {"intensity", "radius", "smoothness", "roundness"});
  if (j.contains("intensity")) v->intensity = number(j["intensity"], "/post/vignette/intensity", 0, 1);
  if (j.contains("radius")) v->radius = number(j["radius"], "/post/vignette/radius", 0, 4);
  if (j.contains("smoothness")) v->smoothness = number(j["smoothness"], "/post/vignette/smoothness", 0, 4);
  if (j.contains("roundness")) v->roundness = number(j["roundness"], "/post/vignette/roundness", 0, 1);
}

// Bloom's levels are bounded by kMaxBloomLevels here; a frame whose quarter-resolution image has
// fewer mips renders that many (render_path.h bloomLevelSizes), since the scene's size may change.
void bloom(const json& j, BloomSettings* b) {
  onlyKeys(j, "/post/bloom", {"intensity", "levels", "threshold"});
  if (j.contains("intensity")) b->intensity = number(j["intensity"], "/post/bloom/intensity", 0, 1);
  if (j.contains("levels"))
    b->levels = int(wholeNumber(j["levels"], "/post/bloom/levels", 1, uint32_t(kMaxBloomLevels)));
  if (j.contains("threshold")) b->threshold = number(j["threshold"], "/post/bloom/threshold", 0, 65504);
}

// The effects of the post pass. The tone curves are those the runtime embeds a post variant for
// (compiler/post.h ToneCurve; a backend refuses any other); grading, vignette and bloom are on when given.
void post(const json& j, const AssetPaths& assets, Scene* s) {
  onlyKeys(j, "/post", {"toneCurve", "dither", "grading", "vignette", "bloom"});
  PostSettings& p = s->post;
  if (j.contains("toneCurve")) {
    p.toneCurve = string(j["toneCurve"], "/post/toneCurve");
    if (p.toneCurve != "aces" && p.toneCurve != "neutral" && p.toneCurve != "none")
      fail("/post/toneCurve",
           "expected \"aces\", \"neutral\" or \"none\", not '" + scene::shownValue(p.toneCurve) + "'");
  }
  if (j.contains("dither")) {
    if (!j["dither"].is_boolean()) fail("/post/dither", "expected true or false");
    p.dither = j["dither"].get<bool>();
  }
  if (j.contains("grading")) {
    grading(j["grading"], assets, s);
    p.colorGrading = true;
  }
  if (j.contains("vignette")) {
    vignette(j["vignette"], &s->vignette);
    p.vignette = true;
  }
  if (j.contains("bloom")) {
    bloom(j["bloom"], &s->bloom);
    p.bloom = true;
  }
}

// "antialiasing": {"msaa": N, "fxaa": bool}, N the forward pass's samples per pixel
// (render_path.h); fxaa an FXAA pass after the post pass.
void antialiasing(const json& j, Scene* s) {
  onlyKeys(j, "/antialiasing", {"msaa", "fxaa"});
  if (j.contains("msaa")) {
    const uint32_t n = wholeNumber(j["msaa"], "/antialiasing/msaa", 1, 4);
    if (n == 3) fail("/antialiasing/msaa", "expected 1, 2 or 4 samples, not 3");
    s->msaaSamples = n;
  }
  if (j.contains("fxaa")) {
    if (!j["fxaa"].is_boolean()) fail("/antialiasing/fxaa", "expected true or false");
    s->fxaa = j["fxaa"].get<bool>();
  }
}

// "shadows": the sun's atlas and cascades (docs/shadows.md). The atlas is square and a power of
// two so that texel snapping and the cascades' rectangles divide it exactly; 8192 is the largest
// 2D image every Vulkan 1.0 and GLES 3.0 device class Facet targets may allow (the device's own
// limit is checked again when the atlas is made).
ShadowSettings shadows(const json& j) {
  onlyKeys(j, "/shadows",
           {"atlasSize", "cascades", "distance", "splitLambda", "depthBias", "slopeBias", "normalBias", "slopeStage"});
  ShadowSettings s;
  if (j.contains("atlasSize")) {
    s.atlasSize = wholeNumber(j["atlasSize"], "/shadows/atlasSize", 256, kMaxShadowAtlasSize);
    if ((s.atlasSize & (s.atlasSize - 1)) != 0)
      fail("/shadows/atlasSize", "expected a power of two, not " + std::to_string(s.atlasSize));
  }
  if (j.contains("cascades")) s.cascades = wholeNumber(j["cascades"], "/shadows/cascades", 1, 4);
  if (j.contains("distance")) s.distance = number(j["distance"], "/shadows/distance", 0.01, 1e6);
  if (j.contains("splitLambda")) s.splitLambda = number(j["splitLambda"], "/shadows/splitLambda", 0, 1);
  if (j.contains("depthBias")) s.depthBias = number(j["depthBias"], "/shadows/depthBias", 0, 64);
  if (j.contains("slopeBias")) s.slopeBias = number(j["slopeBias"], "/shadows/slopeBias", 0, 64);
  if (j.contains("normalBias")) s.normalBias = number(j["normalBias"], "/shadows/normalBias", 0, 64);
  constexpr const char* kSlopeStages[] = {"raster", "vertex"};
  if (j.contains("slopeStage"))
    s.slopeStage = SlopeBiasStage(oneOf(j["slopeStage"], "/shadows/slopeStage", kSlopeStages));
  return s;
}

// `show`: "environment" (at `lod`, × `intensity`) or "flat" (the mean radiance, which takes neither).
Background background(const json& j, bool hasEnvironment) {
  onlyKeys(j, "/background", {"show", "lod", "intensity"});
  Background b;
  b.environment = hasEnvironment;
  constexpr const char* kShows[] = {"environment", "flat"};
  if (j.contains("show")) b.environment = oneOf(j["show"], "/background/show", kShows) == 0;
  for (const char* key : {"lod", "intensity"})
    if (!b.environment && j.contains(key))
      fail(std::string("/background/") + key, "applies to the environment drawn, not to \"show\": \"flat\"");
  if (j.contains("lod")) b.lod = number(j["lod"], "/background/lod", 0, kMaxBackgroundLod);
  // At most 16: the shader's radiance stays mediump-finite (templates/post_background.frag.glsl).
  if (j.contains("intensity")) b.intensity = number(j["intensity"], "/background/intensity", 0, 16);
  return b;
}

Scene scene(const json& j, const AssetPaths& assets) {
  onlyKeys(j, "",
           {"width", "height", "tier", "camera", "sun", "lights", "sky", "environment", "objects", "post",
            "antialiasing", "renderScale", "shadows", "background"});
  Scene s;
  if (j.contains("width")) s.width = wholeNumber(j["width"], "/width", 1, 4096);
  if (j.contains("height")) s.height = wholeNumber(j["height"], "/height", 1, 4096);
  if (j.contains("tier")) s.tier = string(j["tier"], "/tier");
  if (j.contains("camera")) s.camera = camera(j["camera"]);
  if (j.contains("post")) post(j["post"], assets, &s);
  if (j.contains("antialiasing")) antialiasing(j["antialiasing"], &s);
  // The range of render_path.h's isRenderScale (the scene library does not link the runtime).
  if (j.contains("renderScale")) s.renderScale = number(j["renderScale"], "/renderScale", 0.5, 1.0);
  if (j.contains("sun")) s.sun = sun(j["sun"]);
  if (j.contains("shadows")) s.shadows = shadows(j["shadows"]);
  if (j.contains("lights")) {
    if (!j["lights"].is_array()) fail("/lights", "expected an array of lights");
    if (j["lights"].size() > kMaxSceneLights)
      fail("/lights", std::to_string(j["lights"].size()) + " lights; a scene has at most " +
                          std::to_string(kMaxSceneLights) + " point and spot lights");
    for (size_t i = 0; i < j["lights"].size(); ++i) {
      const std::string pointer = "/lights/" + std::to_string(i);
      s.lights.push_back(light(j["lights"][i], pointer));
      if (s.lights.back().castShadows && shadowSpotLights(s).size() > kMaxShadowSpotLights)
        fail(pointer + "/castShadows", "a scene has at most " + std::to_string(kMaxShadowSpotLights) +
                                           " spot light casting shadows (docs/shadows.md, \"Spot shadows\")");
    }
  }
  if (j.contains("sky")) {
    onlyKeys(j["sky"], "/sky", {"luminance"});
    if (j["sky"].contains("luminance")) s.skyLuminance = number(j["sky"]["luminance"], "/sky/luminance", 0, 1e6);
  }
  if (j.contains("environment")) {
    // Two sources of ambient light would leave one of them silently unused.
    if (j.contains("sky"))
      fail("/environment", "give either 'sky' (a constant environment) or 'environment', not both");
    s.environment = environment(j["environment"], assets);
  }
  s.background.environment = s.environment.has_value();
  if (j.contains("background")) s.background = background(j["background"], s.environment.has_value());
  if (!j.contains("objects") || !j["objects"].is_array()) fail("/objects", "expected an array of objects");
  if (j["objects"].size() > 4096) fail("/objects", "more than 4096 objects");
  for (size_t i = 0; i < j["objects"].size(); ++i)
    s.objects.push_back(object(j["objects"][i], "/objects/" + std::to_string(i), assets));
  return s;
}

}  // namespace

uint32_t sunShadowCascades(const Scene& s) { return s.sun && s.sun->castShadows ? s.shadows.cascades : 0; }

glm::dmat4 viewProjection(const Scene& s) {
  const Camera& cam = s.camera;
  const glm::dmat4 view = glm::lookAt(cam.position, cam.target, cam.up);
  return glm::perspective(glm::radians(cam.fovYDegrees), double(s.width) / s.height, cam.nearPlane, cam.farPlane) *
         view;
}

glm::dmat4 modelMatrix(const SceneObject& o) {
  return glm::translate(glm::dmat4(1), o.position) * glm::mat4_cast(o.rotation) *
         glm::scale(glm::dmat4(1), o.radius * o.scale);
}

std::optional<Scene> parseScene(const std::string& path, const std::string& text, std::string* error,
                                const SceneReadOptions& options) {
  std::optional<json> j = scene::parseJsonDocument(path, text, error);
  if (!j) return std::nullopt;
  try {
    const AssetPaths assets(std::filesystem::path(path).parent_path(), options.assetRoot);
    Scene s = scene(*j, assets);
    s.assetRoot = assets.root().string();
    return s;
  } catch (const SceneError& e) {
    *error = path + ": error: " + (e.pointer.empty() ? "/" : e.pointer) + ": " + e.message;
  } catch (const json::exception& e) {
    *error = path + ": error: " + e.what();
  }
  return std::nullopt;
}

std::optional<std::string> readSceneFile(const std::string& path, std::string* error) {
  std::error_code ec;
  auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) {
    *error = path + ": error: cannot open the scene file: no such file";
    return std::nullopt;
  }
  // A FIFO or device would block or never end: only regular files are read.
  if (!std::filesystem::is_regular_file(status)) {
    *error = path + ": error: cannot open the scene file: not a regular file";
    return std::nullopt;
  }
  if (std::filesystem::file_size(path, ec) > (16u << 20)) {
    *error = path + ": error: scene files are limited to 16 MiB";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = path + ": error: cannot open the scene file: " + std::strerror(errno);
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    *error = path + ": error: cannot read the scene file: " + std::strerror(errno);
    return std::nullopt;
  }
  return text.str();
}

std::optional<Scene> loadScene(const std::string& path, std::string* error, const SceneReadOptions& options) {
  std::optional<std::string> text = readSceneFile(path, error);
  if (!text) return std::nullopt;
  return parseScene(path, *text, error, options);
}

}  // namespace facet::runtime
