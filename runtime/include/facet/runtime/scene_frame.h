// Turns a scene into a frame a backend can draw: loads each material package once, picks the
// variant the scene needs, packs parameter blocks, and pre-exposes the lights.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "facet/runtime/environment.h"
#include "facet/runtime/material.h"
#include "facet/runtime/material_instance.h"
#include "facet/runtime/render_backend.h"
#include "facet/scene/scene.h"

namespace facet::runtime {

class SceneFrame {
 public:
  // Packages are read from `<packageDir>/<material>.matpkg`.
  static std::unique_ptr<SceneFrame> prepare(const Scene& scene, const std::string& packageDir, std::string* error);

  const FrameDesc& frame() const { return frame_; }
  double exposure() const { return exposure_; }
  // The variant key lit objects use, e.g. "high.dir1" (unlit ones ignore the light axis).
  const std::string& variantKey() const { return variantKey_; }
  // The scene's image-based lighting as uploaded (pre-exposed SH and prefiltered levels).
  const EnvironmentLighting& environment() const { return environment_; }

 private:
  SceneFrame() = default;
  const Texture* texture(const LoadedMaterial::SampledTexture& t, std::string* error);
  std::vector<std::shared_ptr<Material>> materials_;  // one per package the scene names (and receiving)
  // Each casting material's depth-only program (`<tier>.depth`), by material name.
  std::map<std::string, std::unique_ptr<ShaderProgram>> depthPrograms_;
  ColorEncoding colors_ = ColorEncoding::Linear;  // what the scene's tier expects
  // Built-in meshes by name, glTF meshes by resolved path.
  std::map<std::string, std::unique_ptr<Mesh>> meshes_;
  std::map<std::string, std::unique_ptr<Texture>> textures_;  // by image path (or default colour)
  EnvironmentLighting environment_;
  std::unique_ptr<Texture> environmentTexture_;
  std::unique_ptr<Texture> irradianceTexture_;
  ColorLutTexels colorLut_;  // the scene's grading, when it has some
  FrameDesc frame_;
  double exposure_ = 1;
  std::string variantKey_;
};

}  // namespace facet::runtime
