#include "facet/runtime/scene_frame.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <optional>
#include <unordered_map>

#include "facet/permutations/tiers.h"
#include "facet/permutations/variant_key.h"
#include "facet/runtime/background.h"
#include "facet/runtime/color_grading.h"
#include "facet/runtime/compressed_texture.h"
#include "facet/runtime/environment.h"
#include "facet/runtime/exposure.h"
#include "facet/runtime/gltf_mesh.h"
#include "facet/runtime/image_texture.h"
#include "facet/runtime/material_instance.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/mesh_optimize.h"
#include "facet/runtime/scene_image_budget.h"
#include "facet/runtime/shadow_pass.h"
#include "facet/runtime/sun_shadow.h"
#include "facet/runtime/texture_checks.h"
#include "facet/runtime/vignette.h"

namespace facet::runtime {
namespace {

void store(float* dst, const glm::mat4& m) { std::memcpy(dst, glm::value_ptr(m), sizeof(float) * 16); }

// What a draw shares with the draws it may be merged with: all but its instances, as bytes.
std::string instancingKey(const DrawItem& d) {
  std::string key;
  auto add = [&](const void* bytes, size_t size) { key.append(static_cast<const char*>(bytes), size); };
  add(&d.mesh, sizeof d.mesh);
  add(&d.program, sizeof d.program);
  add(&d.materialBlock, sizeof d.materialBlock);
  const bool flags[2] = {d.cullBackFaces, d.masked};
  add(flags, sizeof flags);
  for (const TextureBinding& t : d.textures) {
    add(&t.binding, sizeof t.binding);
    add(&t.texture, sizeof t.texture);
    key += t.glslName + '\0';
  }
  key += '|';
  add(d.materialParams.data(), d.materialParams.size());
  return key;
}

// Opaque objects that differ only in their transform become one instanced draw, at the place of
// the first of them, their instances in scene order. Opaque draws test and write depth, so
// their order changes no pixel except between coplanar surfaces at equal depth (GL_LESS keeps
// the first drawn: the same one as before when both are in one group, since the group keeps
// scene order). Blended draws are not merged: they are sorted far to near, per object, and one
// draw's instances would blend in their own order, whatever the camera.
void mergeInstances(std::vector<DrawItem>* draws) {
  std::vector<DrawItem> merged;
  std::unordered_map<std::string, size_t> groups;
  for (DrawItem& d : *draws) {
    if (d.blending == Blending::Opaque) {
      auto [it, fresh] = groups.try_emplace(instancingKey(d), merged.size());
      if (!fresh && merged[it->second].instances.size() < abi::kMaxInstancesPerDraw) {
        merged[it->second].instances.push_back(d.instances.front());
        continue;
      }
      it->second = merged.size();  // a new group, or the full one's successor
    }
    merged.push_back(std::move(d));
  }
  *draws = std::move(merged);
}
void store(float* dst, const glm::dvec3& v, double w = 0) {
  dst[0] = float(v.x);
  dst[1] = float(v.y);
  dst[2] = float(v.z);
  dst[3] = float(w);
}

// The frame-block form of a punctual light (shader_abi.h, chunks/light_punctual.glsl). A point
// light's cone factor is 1 everywhere: scale 0, offset 1.
void storePunctual(const PunctualLight& light, double exposure, abi::PunctualLightUniforms* out) {
  store(out->positionFalloff, light.position, 1.0 / (light.range * light.range));
  store(out->colorIntensity, light.color * light.intensity * exposure);
  store(out->direction, glm::normalize(light.direction));
  double scale = 0, offset = 1;
  if (light.spot) {
    double cosInner = std::cos(glm::radians(light.innerAngleDegrees));
    double cosOuter = std::cos(glm::radians(light.outerAngleDegrees));
    scale = 1.0 / std::max(cosInner - cosOuter, 1e-4);
    offset = -cosOuter * scale;
  }
  store(out->spotScaleOffset, glm::dvec3(scale, offset, 0));
}

struct MeshBounds {
  glm::dvec3 center;
  double radius = 0;
};

// The sphere about the centre of the mesh's box that holds every vertex.
MeshBounds meshBounds(const Mesh& mesh) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  const size_t count = mesh.vertices.size() / abi::kVertexFloats;
  auto position = [&](size_t v) {
    const float* p = &mesh.vertices[v * abi::kVertexFloats];
    return glm::dvec3(p[0], p[1], p[2]);
  };
  for (size_t v = 0; v < count; ++v) {
    lo = glm::min(lo, position(v));
    hi = glm::max(hi, position(v));
  }
  MeshBounds b;
  if (count == 0) return b;
  b.center = (lo + hi) * 0.5;
  for (size_t v = 0; v < count; ++v) b.radius = std::max(b.radius, glm::length(position(v) - b.center));
  return b;
}

}  // namespace

std::unique_ptr<SceneFrame> SceneFrame::prepare(const Scene& scene, const std::string& packageDir, std::string* error) {
  if (!checkSceneImageBudget(scene, error)) return nullptr;  // before any image is decoded
  std::unique_ptr<SceneFrame> out(new SceneFrame());
  auto tier = permutations::tierFromString(scene.tier);
  if (!tier) {
    *error = "unknown tier '" + scene.tier + "' (reference, high, mid, low)";
    return nullptr;
  }
  static_assert(kMaxSceneLights == size_t(permutations::kMaxPointLights) && kMaxSceneLights == abi::kMaxPunctualLights,
                "the scene, the permutations and the frame block agree on the punctual-light limit");
  const int lights = int(scene.lights.size());
  out->variantKey_ = permutations::requestKey({true}, *tier, scene.sun.has_value(), lights).toString();
  // Tiers with the gamma hack light sRGB-encoded colours (chunks/shading_standard.glsl): colour
  // parameters and sRGB textures reach them undecoded. Material overrides cannot change the colour
  // space, so the tier decides it for every variant (no preset has the hack; eval's
  // PreparedFrame overrides this for its swap).
  out->colors_ = permutations::preset(*tier).colorSpace == permutations::ColorSpace::GammaHack ? ColorEncoding::Srgb
                                                                                               : ColorEncoding::Linear;

  // Lights are multiplied by the exposure here, on the CPU, so shaders see O(1) values
  // (chunks/precision.glsl: the pre-exposure contract that keeps mediump finite).
  const Camera& cam = scene.camera;
  out->exposure_ = exposureFromEv100(ev100(cam.aperture, cam.shutterSeconds, cam.iso));
  abi::FrameUniforms& f = out->frame_.frame;
  store(f.viewProjection, glm::mat4(viewProjection(scene)));
  store(f.cameraPosition, cam.position, 1);
  if (scene.sun) {
    store(f.lightDirection, -glm::normalize(scene.sun->direction));
    store(f.lightColor, scene.sun->color * scene.sun->illuminance * out->exposure_);
  }
  // Slot order: the casting spot first, whose shadow `.sp1` receivers read for slot 0
  // (docs/shadows.md, "Spot shadows"), then the other lights in scene order.
  const std::vector<size_t> spots = shadowSpotLights(scene);
  std::vector<size_t> slots = spots;
  for (size_t i = 0; i < scene.lights.size(); ++i)
    if (std::find(spots.begin(), spots.end(), i) == spots.end()) slots.push_back(i);
  for (size_t slot = 0; slot < slots.size(); ++slot)
    storePunctual(scene.lights[slots[slot]], out->exposure_, &f.punctualLights[slot]);
  // Image-based lighting, pre-exposed like the lights: SH in the frame block, the prefiltered
  // environment and the irradiance cube for every lit variant, the DFG table for the tiers whose
  // ambient model reads it.
  auto lighting = buildEnvironmentLighting(scene, out->exposure_, error);
  if (!lighting) return nullptr;
  out->environment_ = std::move(*lighting);
  for (size_t k = 0; k < abi::kShFrameCoefficients; ++k)
    for (size_t c = 0; c < 3; ++c) f.sh[k][c] = out->environment_.sh[k][c];
  const auto& mean = out->environment_.meanRadiance;
  store(f.ambient, glm::dvec3(mean[0], mean[1], mean[2]));
  out->environmentTexture_ = std::make_unique<Texture>(environmentTexture(out->environment_));
  out->frame_.frameTextures.push_back(
      {abi::kEnvironmentBinding, abi::kEnvironmentName, out->environmentTexture_.get()});
  out->irradianceTexture_ = std::make_unique<Texture>(irradianceTexture(out->environment_));
  out->frame_.frameTextures.push_back({abi::kIrradianceBinding, abi::kIrradianceName, out->irradianceTexture_.get()});
  if (permutations::preset(*tier).ambient == permutations::AmbientModel::SplitSum)
    out->frame_.frameTextures.push_back({abi::kDfgLutBinding, abi::kDfgLutName, &dfgTexture()});
  out->frame_.width = scene.width;
  out->frame_.height = scene.height;
  if (scene.post.colorGrading) {
    std::optional<ColorLut> lut =
        scene.gradingLut.empty() ? buildColorLut(scene.grading) : loadCubeLut(scene.gradingLut, error);
    if (!lut) return nullptr;
    out->colorLut_ = colorLutTexels(*lut);
    out->frame_.colorLut = &out->colorLut_;
  }
  if (scene.post.vignette) out->frame_.postUniforms = postUniforms(scene.vignette, scene.width, scene.height);
  // The clear colour is the environment's mean: the flat background (exact for a constant sky),
  // and what shows where a drawn background is not (never, as it covers the screen).
  for (int i = 0; i < 3; ++i) out->frame_.clearColor[i] = mean[size_t(i)];

  const int cascades = int(sunShadowCascades(scene));
  const bool spotCasts = !spots.empty();
  const bool shadowPass = cascades > 0 || spotCasts;
  // Material name, and whether its objects receive the shadows -> index in materials_: a
  // material whose objects differ in receiving is loaded once per variant.
  std::map<std::pair<std::string, bool>, size_t> loaded;
  std::vector<CasterBounds> casterBounds;
  std::vector<DrawItem> casters;
  // The scene's glTF files share one budget (vertices, indices, bytes read), each checked before
  // its mesh is built: a scene may name 4096 files.
  GltfBudget meshBudget;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    const bool receives = shadowPass && o.receiveShadows;
    auto [it, fresh] = loaded.emplace(std::make_pair(o.material, receives), out->materials_.size());
    if (fresh) {
      std::string path = (std::filesystem::path(packageDir) / (o.material + ".matpkg")).string();
      auto loadedMaterial = LoadedMaterial::load(path, error);
      if (!loadedMaterial) return nullptr;
      // A package renamed or copied under another material's name would draw the wrong surface.
      if (loadedMaterial->info().name != o.material) {
        *error =
            path + ": holds material '" + loadedMaterial->info().name + "', not '" + o.material + "' as the scene asks";
        return nullptr;
      }
      // The variant, its shaders and package textures, the colour encoding: as for an app's
      // Material (runtime/material_instance.h).
      auto material = Material::create(
          std::move(*loadedMaterial),
          {scene.tier, scene.sun.has_value(), lights, receives ? cascades : 0, receives && spotCasts}, error);
      if (!material) return nullptr;
      const package::MaterialInfo& info = material->loaded().info();
      if (shadowPass && permutations::blendingCastsShadows(info.blending) && !out->depthPrograms_.count(o.material)) {
        // The scene's slope stage picks the program: `.depth.slope` adds the bias in its vertex stage.
        const bool vertexSlope = scene.shadows.slopeStage == SlopeBiasStage::Vertex;
        auto depth = material->loaded().program(permutations::depthKey(*tier, vertexSlope).toString(), error);
        if (!depth) return nullptr;
        out->depthPrograms_[o.material] = std::make_unique<ShaderProgram>(std::move(*depth));
      }
      out->materials_.push_back(std::move(material));
    }
    const Material& material = *out->materials_[it->second];
    DrawItem draw;
    // One Mesh per built-in name or file, built when first named and shared by every object that
    // names it (and so one GPU buffer). A file's path never equals a built-in name: it ends in
    // .gltf or .glb (scene.cpp). A file drawn by glTF material is read once, split into one Mesh
    // per material, each under "<path>\n<material>" (a material missing once the file is read is
    // an error, so a file is never read twice).
    const auto materialKey = [&](int index) { return o.mesh + "\n" + std::to_string(index); };
    if (o.gltfMaterial && !out->meshes_.count(materialKey(*o.gltfMaterial))) {
      std::optional<std::map<int, Mesh>> split =
          loadGltfMeshesByMaterial(o.mesh, error, {scene.assetRoot, &meshBudget});
      if (!split) {
        *error = "object " + std::to_string(i) + ": " + *error;
        return nullptr;
      }
      for (auto& [index, part] : *split) {
        optimizeMesh(&part);
        out->meshes_[materialKey(index)] = std::make_unique<Mesh>(std::move(part));
      }
      if (!out->meshes_.count(materialKey(*o.gltfMaterial))) {
        *error = "object " + std::to_string(i) + ": " + o.mesh + ": error: no primitive of the file's scene " +
                 (*o.gltfMaterial < 0 ? std::string("is without a material")
                                      : "uses /materials/" + std::to_string(*o.gltfMaterial)) +
                 " (the object's gltfMaterial)";
        return nullptr;
      }
    }
    auto [mesh, added] = out->meshes_.try_emplace(o.gltfMaterial ? materialKey(*o.gltfMaterial) : o.mesh);
    if (added) {
      std::optional<Mesh> made = o.mesh == "sphere"  ? makeSphere()
                                 : o.mesh == "plane" ? makePlane()
                                 : o.mesh == "box"   ? makeBox()
                                                     : loadGltfMesh(o.mesh, error, {scene.assetRoot, &meshBudget});
      if (!made) {
        out->meshes_.erase(mesh);
        *error = "object " + std::to_string(i) + ": " + *error;
        return nullptr;
      }
      // Built-in and glTF meshes are reordered for the vertex cache once, here (mesh_optimize.h).
      optimizeMesh(&*made);
      mesh->second = std::make_unique<Mesh>(std::move(*made));
    }
    draw.mesh = mesh->second.get();
    draw.program = &material.program();
    // The normal's transform is derived in the vertex stage from these rows (forward.vert.glsl).
    const glm::mat4 model(modelMatrix(o));
    draw.instances.push_back(instanceTransform(glm::value_ptr(model)));
    auto block = material.loaded().paramBlock(o.params, error, out->colors_, o.boolParams);
    if (!block || !material.loaded().preshade(material.variantKey(), &*block, error)) {
      *error = "object " + std::to_string(i) + ": " + *error;
      return nullptr;
    }
    draw.materialParams = std::move(*block);
    draw.cullBackFaces = !material.doubleSided();
    draw.blending = material.blending();
    draw.masked = material.masked();
    auto sampled = material.loaded().sampledTextures(o.textures, error);
    if (!sampled) {
      *error = "object " + std::to_string(i) + ": " + *error;
      return nullptr;
    }
    for (const auto& [name, sampler] : o.samplers) {
      bool texture = false;
      for (const package::Param& p : material.loaded().info().params)
        texture = texture || (p.name == name && package::isTexture(p.type));
      if (!texture) {
        *error = "object " + std::to_string(i) + ": /objects/" + std::to_string(i) + "/samplers/" + name +
                 ": material '" + o.material + "' has no texture parameter '" + name + "'";
        return nullptr;
      }
    }
    draw.textures = material.generatedTextures();
    for (const LoadedMaterial::SampledTexture& t : *sampled) {
      const Texture* texture = out->texture(t, error);
      if (!texture) {
        *error = "object " + std::to_string(i) + ": " + *error;
        return nullptr;
      }
      TextureBinding binding{abi::kMaterialTextureBase + t.slot, t.glslName, texture, std::nullopt};
      if (auto given = o.samplers.find(t.param); given != o.samplers.end()) binding.sampler = given->second;
      draw.textures.push_back(std::move(binding));
    }
    // A caster: drawn into the atlas with its material's depth-only program, bounded by its mesh's
    // sphere carried into the world (the largest axis scale bounds the radius).
    if (auto depth = out->depthPrograms_.find(o.material); depth != out->depthPrograms_.end() && o.castShadows) {
      DrawItem caster = draw;
      caster.program = depth->second.get();
      casters.push_back(std::move(caster));
      const MeshBounds bounds = meshBounds(*draw.mesh);
      const glm::dmat4 m = modelMatrix(o);
      const double scale =
          std::max({glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])), glm::length(glm::dvec3(m[2]))});
      casterBounds.push_back({glm::dvec3(m * glm::dvec4(bounds.center, 1.0)), bounds.radius * scale});
    }
    out->frame_.draws.push_back(std::move(draw));
  }
  if (shadowPass) out->frame_.shadow = shadowPassDesc(scene, casterBounds, std::move(casters));
  mergeInstances(&out->frame_.draws);
  // Opaque draws first, in scene order (of each draw's first object); blended ones after them,
  // far to near, so each blends over everything behind it (sorted by object centre: exact for
  // the separate spheres here).
  auto& draws = out->frame_.draws;
  auto distance = [&](const DrawItem& d) {
    const abi::InstanceTransform& t = d.instances.front();
    glm::dvec3 centre(t.rows[0][3], t.rows[1][3], t.rows[2][3]);
    return glm::length(centre - cam.position);
  };
  std::stable_sort(draws.begin(), draws.end(), [&](const DrawItem& a, const DrawItem& b) {
    bool blendedA = a.blending != Blending::Opaque, blendedB = b.blending != Blending::Opaque;
    if (blendedA != blendedB) return blendedB;
    return blendedA && distance(a) > distance(b);
  });
  static_assert(kMaxBackgroundLod == abi::kEnvironmentLevels - 1,
                "the scene's background levels are the environment's");
  if (scene.background.environment)
    addBackground(&out->frame_, {float(scene.background.lod), float(scene.background.intensity)});
  return out;
}

const Texture* SceneFrame::texture(const LoadedMaterial::SampledTexture& t, std::string* error) {
  // One texture per image file (or default colour) and encoding, shared by every object using it.
  const bool decode = t.srgb && colors_ == ColorEncoding::Linear;
  std::string key = (t.srgb ? (decode ? "srgb:" : "srgb-undecoded:") : "linear:") + t.imagePath;
  if (t.imagePath.empty())
    for (double c : t.defaultValue) key += ":" + std::to_string(c);
  if (auto it = textures_.find(key); it != textures_.end()) return it->second.get();
  std::optional<Texture> made;
  if (t.imagePath.empty()) {
    made = solidTexture(t.defaultValue, t.srgb);
  } else {
    made = loadTextureFile(t.imagePath, t.srgb, error);
    if (!made) return nullptr;
  }
  // Mip levels were still averaged in linear light; only the sampler's decoding is skipped.
  if (t.srgb && !decode) made->format = withoutSrgbDecode(made->format);
  return textures_.emplace(key, std::make_unique<Texture>(std::move(*made))).first->second.get();
}

}  // namespace facet::runtime
