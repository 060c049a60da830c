// What both example apps draw, whatever the graphics API (examples/app on Vulkan, examples/app_gl
// on OpenGL ES): one material made once from package bytes the app holds, two instances of it with
// different parameters, a sphere mesh, a camera, the sun and the analytic sky (drawn as the background), pre-exposed.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "facet/runtime/material_instance.h"
#include "facet/runtime/render_backend.h"

namespace facet::example {

struct ExampleContent {
  static constexpr uint32_t kWidth = 480;
  static constexpr uint32_t kHeight = 240;
  static constexpr int kFrames = 4;

  // Must outlive the material: loadFromMemory keeps views of them (an asset system, an APK).
  std::vector<uint8_t> packageBytes;
  std::shared_ptr<runtime::Material> material;
  std::unique_ptr<runtime::MaterialInstance> glossy, rough;
  std::optional<runtime::ParameterHandle> roughness;
  runtime::Texture environment;  // frame.frameTextures points here: an ExampleContent stays put
  runtime::Texture irradiance;
  runtime::Mesh sphere;
  runtime::FrameDesc frame;

  ExampleContent() = default;
  ExampleContent(const ExampleContent&) = delete;
  ExampleContent& operator=(const ExampleContent&) = delete;

  // Reads the package, makes the material and its instances, and the frame without draws.
  bool create(const char* packagePath, std::string* error);
  // Frame i: `rough`'s roughness animates (only its block is uploaded again), both spheres drawn.
  bool animate(int i, std::string* error);
  // After kFrames frames: one mesh buffer uploaded once, two blocks (both on the first frame, then
  // `rough` once per later frame). Empty when so, else what the counts were.
  std::string checkResources(const runtime::ResourceCounts& counts) const;
  // The instances differ where it shows in the RGBA8 image (rows top first): the glossy one red,
  // the rough one blue. Empty when so, else the colours seen.
  std::string checkInstances(const std::vector<uint8_t>& rgba) const;
};

}  // namespace facet::example
