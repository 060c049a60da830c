// The environment drawn as the background (runtime/background.h, templates/post_background.*.glsl)
// on both backends: each background pixel is the prefiltered environment's radiance along the
// camera ray through the pixel's centre (the ray from the scene's camera, not from the shader's
// matrix), pre-exposed and × intensity in HDR and through the tone curve in LDR; a mirrored y
// would not pass; objects stay in front of it; Vulkan and GLES agree; validation stays clean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "facet/ibl/cube_map.h"
#include "facet/runtime/background.h"
#include "facet/runtime/png.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using namespace facet::runtime;

constexpr uint32_t kWidth = 96, kHeight = 64;
constexpr double kFovY = 60;
// An unlit sphere left of centre: its pixels show it, whatever the background.
const char* kUnlit = "material unlit_grey { shading unlit\n surface { baseColor = vec3(0.25, 0.25, 0.25) } }";

// An equirect environment whose colour changes with longitude (red, blue) and latitude (green),
// smoothly and periodically so no seam breaks the bilinear comparison: a mirrored y or x, or a
// wrong rotation, gives other colours.
std::string writeEnvironment(const std::string& dir) {
  const uint32_t w = 128, h = 64;
  std::vector<uint8_t> rgba(size_t(w) * h * 4);
  for (uint32_t row = 0; row < h; ++row)
    for (uint32_t column = 0; column < w; ++column) {
      const double longitude = 2 * M_PI * (column + 0.5) / w, latitude = M_PI * (row + 0.5) / h;
      uint8_t* p = &rgba[(size_t(row) * w + column) * 4];
      p[0] = uint8_t(std::lround(127.5 + 100 * std::cos(longitude)));
      p[1] = uint8_t(std::lround(127.5 + 110 * std::cos(latitude)));
      p[2] = uint8_t(std::lround(127.5 + 100 * std::sin(longitude)));
      p[3] = 255;
    }
  std::string error;
  EXPECT_TRUE(writePng(dir + "/env.png", w, h, rgba, &error)) << error;
  return "env.png";
}

struct Rendered {
  FrameResult result;
  EnvironmentLighting environment;
  Scene scene;
};

const std::string& packages() {
  static const std::string dir = facet::test::writePackagesFromTexts("background-packages", {kUnlit});
  return dir;
}

// `background`: the scene's "background" value, or empty for the default.
std::optional<Scene> testScene(const std::string& background) {
  static const std::string dir = facet::test::scratchDir("background-scene");
  static const std::string image = writeEnvironment(dir);
  const std::string json = R"({"width": 96, "height": 64, "tier": "high",
    "camera": {"position": [0, 0, 0], "target": [0.3, 0.2, -1], "up": [0, 1, 0], "fovY": 60,
               "near": 0.1, "far": 100, "aperture": 16, "shutter": 0.008, "iso": 100},
    "environment": {"image": ")" +
                           image + R"(", "luminance": 4000},)" +
                           (background.empty() ? "" : R"("background": )" + background + ",") +
                           R"("objects": [{"mesh": "sphere", "material": "unlit_grey", "position": [-0.9, 0.2, -3],
                    "radius": 0.4}]})";
  std::string error;
  auto scene = parseScene(dir + "/scene.json", json, &error);
  EXPECT_TRUE(scene) << error;
  return scene;
}

Rendered render(bool vulkan, const std::string& background, const char* toneCurve = "aces") {
  Rendered out;
  std::string error;
  auto scene = testScene(background);
  if (!scene) return out;
  out.scene = *scene;
  auto frame = SceneFrame::prepare(*scene, packages(), &error);
  EXPECT_TRUE(frame) << error;
  if (!frame) return out;
  out.environment = frame->environment();
  PostSettings post;
  post.toneCurve = toneCurve;
  std::unique_ptr<RenderBackend> backend;
  if (vulkan) {
    VulkanOptions options;
    options.validation = true;
    options.post = post;
    backend = createVulkanBackend(options, &error);
  } else {
    GlOptions options;
    options.post = post;
    backend = createGlBackend(options, &error);
  }
  EXPECT_TRUE(backend) << error;
  if (!backend) return out;
  EXPECT_TRUE(backend->render(frame->frame(), &out.result, &error)) << error;
  EXPECT_TRUE(backend->validationErrors().empty()) << backend->validationErrors().front();
  return out;
}

// The camera ray through the centre of pixel (column, row), rows top to bottom, from the scene's
// camera (look-at frame, vertical field of view, the image's aspect); mirrorY reads the pixel
// from the other end of its column, as a renderer with a flipped y would show it.
glm::dvec3 cameraRay(const Scene& scene, uint32_t column, uint32_t row, bool mirrorY = false) {
  const Camera& c = scene.camera;
  const glm::dvec3 forward = glm::normalize(c.target - c.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, c.up));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tanHalf = std::tan(kFovY / 2 * M_PI / 180), aspect = double(kWidth) / kHeight;
  const double x = (column + 0.5) / kWidth * 2 - 1;
  double y = 1 - (row + 0.5) / kHeight * 2;
  if (mirrorY) y = -y;
  return forward + right * (x * tanHalf * aspect) + up * (y * tanHalf);
}

// The GPU's trilinear lookup between the two levels around `lod`, on the CPU.
glm::dvec3 environmentRadiance(const EnvironmentLighting& environment, glm::dvec3 d, double lod) {
  auto level = [&](size_t m) {
    facet::ibl::CubeImage cube(int(environment.width >> m));
    cube.rgb = environment.levels[m];
    const facet::ibl::Vec3 v = facet::ibl::sampleBilinear(cube, {d.x, d.y, d.z});
    return glm::dvec3(v.x, v.y, v.z);
  };
  const size_t below = size_t(std::floor(lod)), above = std::min(below + 1, environment.levels.size() - 1);
  return glm::mix(level(below), level(above), lod - double(below));
}

double acesFitted(double x) {
  x = std::clamp(x, 0.0, 160.0);
  return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
double srgbEncoded(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c < 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// Whether pixel (column, row) is well clear of the sphere (its disc plus two pixels).
bool clearOfSphere(const Scene& scene, uint32_t column, uint32_t row) {
  const SceneObject& o = scene.objects.at(0);
  const glm::dvec3 ray = glm::normalize(cameraRay(scene, column, row));
  const glm::dvec3 toCentre = o.position - scene.camera.position;
  const double angle = std::acos(std::clamp(glm::dot(ray, glm::normalize(toCentre)), -1.0, 1.0));
  const double pixelAngle = kFovY * M_PI / 180 / kHeight;
  return angle > std::asin(o.radius / glm::length(toCentre)) + 2 * pixelAngle;
}

struct Worst {
  double hdr = 0;  // the largest |GPU − CPU| / (CPU + 0.02) over the channels of background pixels
  int ldr = 0;     // the largest difference in 8-bit steps from the CPU's tone-mapped value
  size_t pixels = 0;
};

Worst compare(const Rendered& r, double lod, double intensity, bool mirrorY = false) {
  Worst worst;
  if (r.result.hdr.size() != size_t(kWidth) * kHeight * 4 || r.result.ldr.size() != r.result.hdr.size()) {
    ADD_FAILURE() << "no image read back";
    return worst;
  }
  for (uint32_t row = 0; row < kHeight; ++row)
    for (uint32_t column = 0; column < kWidth; ++column) {
      if (!clearOfSphere(r.scene, column, row)) continue;
      ++worst.pixels;
      const glm::dvec3 expected =
          environmentRadiance(r.environment, cameraRay(r.scene, column, row, mirrorY), lod) * intensity;
      const size_t i = (size_t(row) * kWidth + column) * 4;
      for (int c = 0; c < 3; ++c) {
        worst.hdr = std::max(worst.hdr, std::abs(r.result.hdr[i + c] - expected[c]) / (expected[c] + 0.02));
        const int ldr = int(std::lround(255 * srgbEncoded(acesFitted(expected[c]))));
        worst.ldr = std::max(worst.ldr, std::abs(int(r.result.ldr[i + c]) - ldr));
      }
    }
  return worst;
}

}  // namespace

// The bounds: the environment is stored as binary16 (2^-11 relative) and both rasterizers filter
// it with 8-bit bilinear weights (an error of up to 1/512 of neighbouring texels' difference, under
// 1 % of the value for this smooth image); the tone curve runs in mediump. Measured: HDR within
// 0.09 % (level 0) and 0.06 % (level 2.5) and LDR within 1 step on both backends (printed).
TEST(Background, EachPixelIsTheEnvironmentAlongItsCameraRay) {
  for (bool vulkan : {true, false}) {
    SCOPED_TRACE(vulkan ? "Vulkan" : "GLES");
    const Rendered r = render(vulkan, "");
    ASSERT_TRUE(r.scene.background.environment) << "a scene with an environment draws it by default";
    const Worst worst = compare(r, 0, 1);
    std::printf("%s: %zu background pixels, HDR within %.4f relative, LDR within %d steps\n",
                vulkan ? "Vulkan" : "GLES", worst.pixels, worst.hdr, worst.ldr);
    EXPECT_GT(worst.pixels, size_t(kWidth) * kHeight * 3 / 4);
    EXPECT_LT(worst.hdr, 0.01);
    EXPECT_LE(worst.ldr, 1);
    // The test sees a mirrored y: the same image compared with the rays of the other end of
    // each column is far outside the bounds.
    const Worst mirrored = compare(r, 0, 1, true);
    EXPECT_GT(mirrored.hdr, 0.2);
    EXPECT_GT(mirrored.ldr, 20);
  }
}

TEST(Background, TheChosenLevelAndIntensityAreDrawn) {
  for (bool vulkan : {true, false}) {
    SCOPED_TRACE(vulkan ? "Vulkan" : "GLES");
    const Rendered r = render(vulkan, R"({"lod": 2.5, "intensity": 0.5})");
    const Worst worst = compare(r, 2.5, 0.5);
    std::printf("%s, level 2.5 × 0.5: HDR within %.4f relative, LDR within %d steps\n", vulkan ? "Vulkan" : "GLES",
                worst.hdr, worst.ldr);
    EXPECT_LT(worst.hdr, 0.01);
    EXPECT_LE(worst.ldr, 1);
    EXPECT_GT(compare(r, 0, 1).hdr, 0.2) << "the default level and intensity would be another image";
  }
}

// The sphere covers its pixels (the background is behind it), and the flat background is the
// environment's mean radiance (the clear colour) everywhere else.
TEST(Background, ObjectsStayInFrontAndFlatIsTheMean) {
  for (bool vulkan : {true, false}) {
    SCOPED_TRACE(vulkan ? "Vulkan" : "GLES");
    const Rendered drawn = render(vulkan, "", "none");
    const Rendered flat = render(vulkan, R"({"show": "flat"})", "none");
    ASSERT_EQ(drawn.result.hdr.size(), size_t(kWidth) * kHeight * 4);
    ASSERT_EQ(flat.result.hdr.size(), drawn.result.hdr.size());
    // The sphere's centre pixel, projected from the scene's camera.
    const SceneObject& o = drawn.scene.objects.at(0);
    const Camera& c = drawn.scene.camera;
    const glm::dvec3 forward = glm::normalize(c.target - c.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, c.up)), up = glm::cross(right, forward);
    const glm::dvec3 d = o.position - c.position;
    const double tanHalf = std::tan(kFovY / 2 * M_PI / 180);
    const double x = glm::dot(d, right) / glm::dot(d, forward) / (tanHalf * kWidth / kHeight);
    const double y = glm::dot(d, up) / glm::dot(d, forward) / tanHalf;
    const size_t column = size_t((x + 1) / 2 * kWidth), row = size_t((1 - y) / 2 * kHeight);
    const size_t centre = (row * kWidth + column) * 4;
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_NEAR(drawn.result.hdr[centre + ch], 0.25, 0.25 / 1024) << "the unlit sphere, not the background";
      EXPECT_NEAR(flat.result.hdr[centre + ch], 0.25, 0.25 / 1024);
    }
    const auto& mean = flat.environment.meanRadiance;
    for (size_t i = 0; i < flat.result.hdr.size(); i += 4) {
      if (!clearOfSphere(flat.scene, uint32_t(i / 4 % kWidth), uint32_t(i / 4 / kWidth))) continue;
      for (size_t ch = 0; ch < 3; ++ch) ASSERT_NEAR(flat.result.hdr[i + ch], mean[ch], mean[ch] / 1024 + 1e-6);
    }
  }
}

TEST(Background, VulkanAndGlesAgree) {
  const Rendered vk = render(true, R"({"lod": 1})");
  const Rendered gl = render(false, R"({"lod": 1})");
  ASSERT_EQ(vk.result.ldr.size(), size_t(kWidth) * kHeight * 4);
  ASSERT_EQ(gl.result.ldr.size(), vk.result.ldr.size());
  int worst = 0;
  size_t beyondOne = 0;
  for (size_t i = 0; i < vk.result.ldr.size(); ++i) {
    const int difference = std::abs(int(vk.result.ldr[i]) - int(gl.result.ldr[i]));
    worst = std::max(worst, difference);
    beyondOne += difference > 1 ? 1 : 0;
  }
  std::printf("Vulkan vs GLES: max %d/255, %zu values beyond 1/255\n", worst, beyondOne);
  EXPECT_LE(worst, 1);
}

// The matrix the shaders read gives each NDC position the camera's ray (up to a positive scale).
TEST(Background, TheMatrixMapsEachPixelToItsCameraRay) {
  const std::optional<Scene> scene = testScene("");
  ASSERT_TRUE(scene);
  std::string error;
  auto frame = SceneFrame::prepare(*scene, packages(), &error);
  ASSERT_TRUE(frame) << error;
  const facet::abi::BackgroundParams params = backgroundParams(frame->frame().frame.viewProjection, {});
  for (uint32_t row : {0u, 31u, 63u})
    for (uint32_t column : {0u, 50u, 95u}) {
      float d[3];
      backgroundDirection(params, float((column + 0.5) / kWidth * 2 - 1), float(1 - (row + 0.5) / kHeight * 2), d);
      const glm::dvec3 expected = glm::normalize(cameraRay(*scene, column, row));
      const glm::dvec3 got = glm::normalize(glm::dvec3(d[0], d[1], d[2]));
      EXPECT_GT(glm::dot(expected, got), 1 - 1e-9) << column << ", " << row;
    }
}
