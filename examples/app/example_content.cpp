#include "example_content.h"

#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <iterator>

#include "facet/runtime/background.h"
#include "facet/runtime/environment.h"
#include "facet/runtime/exposure.h"
#include "facet/runtime/mesh.h"

namespace facet::example {
namespace {

using namespace facet::runtime;

void store(float* dst, const glm::vec3& v, float w = 0) {
  dst[0] = v.x;
  dst[1] = v.y;
  dst[2] = v.z;
  dst[3] = w;
}

std::array<float, 16> modelAt(float x) {
  std::array<float, 16> m{};
  const glm::mat4 model = glm::translate(glm::mat4(1), glm::vec3(x, 0, 0));
  std::memcpy(m.data(), glm::value_ptr(model), sizeof m);
  return m;
}

}  // namespace

bool ExampleContent::create(const char* packagePath, std::string* error) {
  std::ifstream in(packagePath, std::ios::binary);
  if (!in) {
    *error = std::string("cannot read ") + packagePath;
    return false;
  }
  packageBytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  auto loaded = LoadedMaterial::loadFromMemory(packageBytes, packagePath, error);
  if (!loaded) return false;
  material = Material::create(std::move(*loaded), {"high", true, 0}, error);
  if (!material) return false;
  std::printf("package: %zu bytes, %llu decompressed to draw variant %s\n", packageBytes.size(),
              static_cast<unsigned long long>(material->loaded().reader().bytesDecompressed()),
              material->variantKey().c_str());
  glossy = material->createInstance();
  rough = material->createInstance();
  roughness = material->parameter("roughness");
  if (!roughness) {
    *error = "the material has no 'roughness' parameter";
    return false;
  }
  if (!glossy->setParameter(*roughness, 0.15f, error) ||
      !rough->setParameter("baseColor", std::array<float, 3>{0.1f, 0.35f, 0.8f}, error) ||
      !rough->setParameter(*roughness, 0.7f, error)) {
    return false;
  }

  // Camera, sun and the analytic sky, pre-exposed (docs/lighting-units.md).
  const double exposure = exposureFromEv100(ev100(16, 1.0 / 125, 100));
  frame.width = kWidth;
  frame.height = kHeight;
  const glm::vec3 eye(0, 0.4f, 6);
  const glm::mat4 viewProjection = glm::perspective(glm::radians(30.0f), float(kWidth) / kHeight, 0.1f, 100.0f) *
                                   glm::lookAt(eye, glm::vec3(0), glm::vec3(0, 1, 0));
  std::memcpy(frame.frame.viewProjection, glm::value_ptr(viewProjection), sizeof frame.frame.viewProjection);
  store(frame.frame.cameraPosition, eye, 1);
  store(frame.frame.lightDirection, glm::normalize(glm::vec3(0.4f, 0.55f, 0.73f)));
  store(frame.frame.lightColor, glm::vec3(1, 0.96f, 0.9f) * float(110000 * exposure));
  Scene sky;  // only its environment is read: the analytic sky at 8000 cd/m², drawn behind the spheres
  sky.environment = Environment{};
  sky.environment->luminance = 8000;
  auto lighting = buildEnvironmentLighting(sky, exposure, error);
  if (!lighting) return false;
  environment = environmentTexture(*lighting);
  irradiance = irradianceTexture(*lighting);
  setEnvironment(frame, *lighting, environment, irradiance);
  sphere = makeSphere();
  return true;
}

bool ExampleContent::animate(int i, std::string* error) {
  if (!rough->setParameter(*roughness, 0.55f + 0.05f * float(i), error)) return false;
  frame.draws = {glossy->draw(sphere, modelAt(-1.15f)), rough->draw(sphere, modelAt(1.15f))};
  addBackground(&frame, {});
  return true;
}

std::string ExampleContent::checkResources(const ResourceCounts& counts) const {
  std::printf("%d frames %ux%u: %zu mesh buffer(s), %llu mesh upload(s), %zu material block(s), %llu block upload(s)\n",
              kFrames, kWidth, kHeight, counts.meshBuffers, static_cast<unsigned long long>(counts.meshUploads),
              counts.materialBuffers, static_cast<unsigned long long>(counts.materialUploads));
  // The sphere and the background's triangle, each uploaded once.
  if (counts.meshBuffers == 2 && counts.meshUploads == 2 && counts.materialBuffers == 2 &&
      counts.materialUploads == uint64_t(2 + kFrames - 1)) {
    return "";
  }
  return "unexpected GPU resource counts";
}

std::string ExampleContent::checkInstances(const std::vector<uint8_t>& rgba) const {
  if (rgba.size() != size_t(kWidth) * kHeight * 4)
    return "the image is not " + std::to_string(kWidth) + "x" + std::to_string(kHeight);
  // The sphere centres project about 88 pixels either side of the middle.
  const auto at = [&](uint32_t x, uint32_t y) { return &rgba[(size_t(y) * kWidth + x) * 4]; };
  const uint8_t* left = at(kWidth / 2 - 88, kHeight / 2);
  const uint8_t* right = at(kWidth / 2 + 88, kHeight / 2);
  if (left[0] > left[2] + 64 && right[2] > right[0] + 64) return "";
  return "the two instances did not draw as set (left rgb " + std::to_string(left[0]) + "," + std::to_string(left[1]) +
         "," + std::to_string(left[2]) + ", right " + std::to_string(right[0]) + "," + std::to_string(right[1]) + "," +
         std::to_string(right[2]) + ")";
}

}  // namespace facet::example
