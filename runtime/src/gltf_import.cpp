// `matc import`: a glTF file's materials as .mat files and a scene (docs/gltf.md).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "facet/package/package.h"
#include "facet/runtime/gltf_materials.h"
#include "gltf_document.h"

namespace facet::runtime {
namespace {

namespace fs = std::filesystem;
using OrderedJson = nlohmann::ordered_json;

const char* const kSlotParameters[kGltfSlots] = {
    "baseColorTexture",          "metallicRoughnessTexture", "normalTexture",         "occlusionTexture",
    "emissiveTexture",           "sheenColorTexture",        "sheenRoughnessTexture", "clearcoatTexture",
    "clearcoatRoughnessTexture", "clearcoatNormalTexture",   "anisotropyTexture"};

// `target` relative to the scene's folder when it lies inside the asset root (all resolved), else "".
std::string relativeInside(const fs::path& sceneFolder, const fs::path& root, const fs::path& target) {
  const fs::path real = fs::weakly_canonical(target);
  const fs::path fromRoot = real.lexically_relative(fs::weakly_canonical(root));
  if (fromRoot.empty() || *fromRoot.begin() == "..") return "";
  return real.lexically_relative(fs::weakly_canonical(sceneFolder)).generic_string();
}

std::string imageExtension(const GltfImage& image) {
  if (image.bytes.size() >= 3 && image.bytes[0] == 0xff && image.bytes[1] == 0xd8) return ".jpg";
  if (image.mimeType == "image/jpeg") return ".jpg";
  return ".png";  // the decoder tells any other format by its bytes and names the file
}

// A scene object's sampler (scene-format.md, "samplers"), every field spelled out.
OrderedJson samplerJson(const TextureSampler& s) {
  const char* const wraps[] = {"repeat", "clampToEdge", "mirroredRepeat"};
  std::string min = s.minLinear ? "linear" : "nearest";
  if (s.mipmaps) min += s.mipLinear ? "MipmapLinear" : "MipmapNearest";
  return {{"wrapS", wraps[size_t(s.wrapS)]},
          {"wrapT", wraps[size_t(s.wrapT)]},
          {"magFilter", s.magLinear ? "linear" : "nearest"},
          {"minFilter", min}};
}

OrderedJson camera(const GltfMaterialSet& set) {
  std::array<double, 3> centre;
  double radius = 0;
  for (size_t c = 0; c < 3; ++c) {
    centre[c] = (set.boundsMin[c] + set.boundsMax[c]) / 2;
    radius += std::pow((set.boundsMax[c] - set.boundsMin[c]) / 2, 2);
  }
  radius = std::max(std::sqrt(radius), 1e-3);
  // The bounding sphere fills the 40° vertical view: distance = radius / sin(20°) ≈ 2.92 radius,
  // from the front (+z, glTF's front) and a little above.
  const double distance = 2.92 * radius, rise = 0.35;
  const double norm = std::sqrt(1 + rise * rise);
  // Near and far bracket the sphere, [distance − radius, distance + radius] = [1.92, 3.92] radius,
  // with room to move the camera halfway in or twice as far out: far / near ≈ 8. Depth is
  // d = f / (f − n) · (1 − n / z), stored as D32F near 1 (24-bit mantissa), so z resolves to about
  // z² / n · 2⁻²⁴: the near plane sets the precision, and far / 400 lost close surfaces (the
  // avocado's pit and flesh) to depth fighting.
  return {{"position", {centre[0], centre[1] + distance * rise / norm, centre[2] + distance / norm}},
          {"target", centre},
          {"fovY", 40},
          {"near", (distance - radius) / 2},
          {"far", (distance + radius) * 2}};
}

}  // namespace

bool importGltf(const std::string& path, const std::string& outDir, const std::string& assetRoot, GltfImport* result,
                std::string* error) {
  const fs::path out(outDir);
  const std::string root = assetRoot.empty() ? outDir : assetRoot;
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) {
    *error = outDir + ": error: cannot create the folder: " + ec.message();
    return false;
  }
  const std::string outside =
      " is outside " + root + ", the folder the scene may read files from (the output folder, or --asset-root)";
  const std::string mesh = relativeInside(out, root, fs::absolute(path));
  if (mesh.empty()) {
    *error = path + ": error: the glTF file" + outside;
    return false;
  }
  GltfReadOptions options;
  options.assetRoot = root;
  auto set = readGltfMaterials(path, error, options);
  if (!set) return false;
  const std::string stem = fs::path(path).stem().string();
  std::vector<package::OutputFile> files;
  std::map<int, std::string> imagePaths;  // /images index -> path relative to the scene
  const auto imagePath = [&](int index) -> std::optional<std::string> {
    if (auto it = imagePaths.find(index); it != imagePaths.end()) return it->second;
    const GltfImage& image = set->images[size_t(index)];
    std::string relative;
    if (!image.bytes.empty()) {
      relative = stem + "_images/" + std::to_string(index) + imageExtension(image);
      files.push_back({(out / relative).string(), image.bytes});
    } else {
      std::string why;
      const std::string file = gltf::uriPath(image.uri, &why);
      if (file.empty()) {
        *error = path + ": error: /images/" + std::to_string(index) + "/uri: " + why;
        return std::nullopt;
      }
      relative = relativeInside(out, root, fs::absolute(fs::path(path).parent_path() / file));
      if (relative.empty()) {
        *error = path + ": error: /images/" + std::to_string(index) + "/uri: the image" + outside;
        return std::nullopt;
      }
    }
    result->images.push_back(relative);
    return imagePaths[index] = relative;
  };

  OrderedJson objects = OrderedJson::array();
  std::set<std::string> written;
  for (const GltfMaterial& m : set->materials) {
    const std::string name = m.features.name();
    if (written.insert(name).second) {
      const std::string source = gltfMaterialSource(m.features);
      files.push_back({(out / (name + ".mat")).string(), {source.begin(), source.end()}});
      result->materials.push_back((out / (name + ".mat")).string());
    }
    OrderedJson params, samplers;
    params["baseColorFactor"] = m.baseColorFactor;
    params["metallicFactor"] = m.metallicFactor;
    params["roughnessFactor"] = m.roughnessFactor;
    params["emissiveFactor"] = m.emissiveFactor;
    params["reflectance"] = m.reflectance();
    if (m.features.textured[size_t(GltfSlot::Normal)]) params["normalScale"] = m.normalScale;
    if (m.features.textured[size_t(GltfSlot::Occlusion)]) params["occlusionStrength"] = m.occlusionStrength;
    if (m.features.sheen) {
      params["sheenColorFactor"] = m.sheenColorFactor;
      params["sheenRoughnessFactor"] = m.sheenRoughnessFactor;
    }
    if (m.features.clearCoat) {
      params["clearcoatFactor"] = m.clearcoatFactor;
      params["clearcoatRoughnessFactor"] = m.clearcoatRoughnessFactor;
      if (m.features.textured[size_t(GltfSlot::ClearCoatNormal)])
        params["clearcoatNormalScale"] = m.clearcoatNormalScale;
    }
    if (m.features.anisotropy) {
      params["anisotropyStrength"] = m.anisotropyStrength;
      params["anisotropyRotation"] =
          std::array<double, 2>{std::cos(m.anisotropyRotation), std::sin(m.anisotropyRotation)};
    }
    for (size_t s = 0; s < kGltfSlots; ++s) {
      if (!m.features.textured[s]) continue;
      const GltfTextureUse& t = m.textures[s];
      auto image = imagePath(t.image);
      if (!image) return false;
      const std::string p = kSlotParameters[s];
      params[p] = *image;
      if (t.transformed) {
        params[p + "Offset"] = t.offset;
        params[p + "Rotation"] = t.rotation;
        params[p + "Scale"] = t.scale;
      }
      if (!(t.sampler == TextureSampler{})) samplers[p] = samplerJson(t.sampler);
    }
    OrderedJson object = {{"mesh", mesh}, {"gltfMaterial", m.index}, {"material", name}, {"params", params}};
    if (!samplers.empty()) object["samplers"] = samplers;
    objects.push_back(object);
  }
  OrderedJson scene = {
      {"width", 480},
      {"height", 360},
      {"tier", "high"},
      {"camera", camera(*set)},
      {"sun", {{"direction", {-0.4, -0.55, -0.73}}, {"illuminance", 110000}, {"color", {1.0, 0.96, 0.9}}}},
      {"sky", {{"luminance", 6000}}},
      {"objects", objects}};
  const std::string text = scene.dump(2) + "\n";
  result->scene = (out / (stem + ".json")).string();
  files.push_back({result->scene, {text.begin(), text.end()}});
  const bool embedded = std::any_of(files.begin(), files.end(), [&](const package::OutputFile& f) {
    return fs::path(f.path).parent_path() == out / (stem + "_images");
  });
  if (embedded) fs::create_directories(out / (stem + "_images"), ec);
  if (ec) {
    *error = outDir + ": error: cannot create the folder: " + ec.message();
    return false;
  }
  if (!package::writeFiles(files, error)) return false;
  result->notes = set->notes;
  return true;
}

}  // namespace facet::runtime
