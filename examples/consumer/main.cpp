// An app built against the installed Facet (find_package(Facet COMPONENTS vulkan), linking
// Facet::runtime_vulkan only): lists what the packages facet_add_materials built contain, then
// renders one frame of the first one on the runtime's own Vulkan device (lavapipe here).
//
//   facet-consumer [--render out.png] <a.matpkg> [<b.matpkg> ...]
//
// Exit status 1 on any error, including a Vulkan validation error when FACET_VK_VALIDATION is set.
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "facet/package/package.h"
#include "facet/package/package_reader.h"
#include "facet/runtime/environment.h"
#include "facet/runtime/exposure.h"
#include "facet/runtime/material.h"
#include "facet/runtime/material_instance.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/png.h"
#include "facet/runtime/render_backend.h"

namespace {

using namespace facet::runtime;

int fail(const std::string& message) {
  std::fprintf(stderr, "facet-consumer: error: %s\n", message.c_str());
  return 1;
}

// One line per parameter and per variant, with each variant's shader bytes per target as stored
// in the file (what an app ships) against decoded.
void list(const std::string& path, const LoadedMaterial& material) {
  const facet::package::PackageReader& reader = material.reader();
  const facet::package::MaterialInfo& info = material.info();
  std::printf("%s: material %s (%s, %s), format %u.%u, %s: %zu parameters, %zu variants\n", path.c_str(),
              info.name.c_str(), info.shading.c_str(), info.blending.c_str(), unsigned(reader.formatMajor()),
              unsigned(reader.formatMinor()), reader.compilerVersion().c_str(), info.params.size(),
              reader.variants().size());
  for (const facet::package::Param& p : info.params)
    std::printf("  parameter %s: %s\n", p.name.c_str(), facet::package::toString(p.type));
  for (const facet::package::VariantInfo& v : reader.variants()) {
    std::printf("  variant %s:", v.key.c_str());
    for (const facet::package::ShaderInfo& s : v.shaders) {
      const facet::package::BlobInfo& blob = reader.blobs()[s.blob];
      std::printf(" %s %s %llu/%llu B", facet::package::toString(s.target), facet::package::toString(s.stage),
                  static_cast<unsigned long long>(blob.storedSize), static_cast<unsigned long long>(blob.rawSize));
    }
    std::printf("\n");
  }
}

void store(float* dst, const glm::vec3& v, float w = 0) {
  dst[0] = v.x;
  dst[1] = v.y;
  dst[2] = v.z;
  dst[3] = w;
}

// The `high` tier with a sun, a constant 6000 cd/m² sky and a camera at f/16 1/125 s ISO 100
// (docs/lighting-units.md): one unit sphere filling the middle of the image.
int render(LoadedMaterial loaded, const std::string& out) {
  std::string error;
  VulkanOptions options;
  const char* validation = std::getenv("FACET_VK_VALIDATION");
  options.validation = validation && *validation && std::strcmp(validation, "0") != 0;
  options.readBackHdr = false;
  auto renderer = createVulkanBackend(options, &error);
  if (!renderer) return fail(error);
  auto material = Material::create(std::move(loaded), {"high", true, 0}, &error);
  if (!material) return fail(error);
  auto instance = material->createInstance();

  const uint32_t width = 160, height = 120;
  const double exposure = exposureFromEv100(ev100(16, 1.0 / 125, 100));
  FrameDesc frame;
  frame.width = width;
  frame.height = height;
  const glm::vec3 eye(0, 0, 4);
  const glm::mat4 viewProjection = glm::perspective(glm::radians(40.0f), float(width) / height, 0.1f, 100.0f) *
                                   glm::lookAt(eye, glm::vec3(0), glm::vec3(0, 1, 0));
  std::memcpy(frame.frame.viewProjection, glm::value_ptr(viewProjection), sizeof frame.frame.viewProjection);
  store(frame.frame.cameraPosition, eye, 1);
  store(frame.frame.lightDirection, glm::normalize(glm::vec3(0.4f, 0.55f, 0.73f)));
  store(frame.frame.lightColor, glm::vec3(1, 0.96f, 0.9f) * float(110000 * exposure));
  Scene sky;  // only its sky is read
  sky.skyLuminance = 6000;
  auto lighting = buildEnvironmentLighting(sky, exposure, &error);
  if (!lighting) return fail(error);
  const Texture environment = environmentTexture(*lighting);
  const Texture irradiance = irradianceTexture(*lighting);
  setEnvironment(frame, *lighting, environment, irradiance);
  const Mesh sphere = makeSphere();
  std::array<float, 16> model{};
  const glm::mat4 identity(1);
  std::memcpy(model.data(), glm::value_ptr(identity), sizeof model);
  frame.draws = {instance->draw(sphere, model)};

  FrameResult result;
  if (!renderer->render(frame, &result, &error)) return fail(error);
  for (const std::string& message : renderer->validationErrors())
    std::fprintf(stderr, "validation: %s\n", message.c_str());
  if (!renderer->validationErrors().empty()) return fail("Vulkan validation errors");
  if (!writePng(out, result.width, result.height, result.ldr, &error)) return fail(error);
  // The sphere covers the centre and not the corner: the two pixels must differ visibly.
  const uint8_t* centre = &result.ldr[(size_t(height / 2) * width + width / 2) * 4];
  const uint8_t* corner = &result.ldr[0];
  int difference = 0;
  for (int c = 0; c < 3; ++c) difference += std::abs(int(centre[c]) - int(corner[c]));
  std::printf("rendered %s with %s (%s) %ux%u: centre rgb %d,%d,%d, corner rgb %d,%d,%d -> %s\n",
              material->loaded().info().name.c_str(), renderer->name(), material->variantKey().c_str(), width, height,
              centre[0], centre[1], centre[2], corner[0], corner[1], corner[2], out.c_str());
  if (difference < 30)
    return fail("the material did not draw (centre and corner differ by " + std::to_string(difference) + ")");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string renderTo;
  std::vector<std::string> packages;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--render" && i + 1 < argc) {
      renderTo = argv[++i];
    } else if (!arg.empty() && arg[0] == '-') {
      packages.clear();
      break;
    } else {
      packages.push_back(arg);
    }
  }
  if (packages.empty()) {
    std::fprintf(stderr, "usage: facet-consumer [--render out.png] <a.matpkg> [<b.matpkg> ...]\n");
    return 2;
  }
  std::vector<LoadedMaterial> loaded;
  for (const std::string& path : packages) {
    std::string error;
    auto material = LoadedMaterial::load(path, &error);
    if (!material) return fail(error);
    list(path, *material);
    loaded.push_back(std::move(*material));
  }
  return renderTo.empty() ? 0 : render(std::move(loaded.front()), renderTo);
}
