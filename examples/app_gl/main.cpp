// An engine's view of Facet on OpenGL ES: the app owns its GLES 3 context (here an EGL surfaceless
// one, where a phone app would have its window's), makes it current, and hands the runtime its
// getProcAddress. Then as examples/app does on Vulkan: one package loaded from memory, two
// instances of its material with different parameters, a few frames, the last written as PNG.
// It links facet_runtime_core and facet_runtime_gl, and EGL for its own context: no OSMesa, no GL
// library of the runtime's, no Vulkan, no scene reader (ctest example_app_gl_link_weight).
//
//   facet-app-gl-example <red_plastic.matpkg> <out.png>
//
// Exit status 1 on any error.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "facet/gl_backend.h"
#include "facet/runtime/environment.h"
#include "facet/runtime/exposure.h"
#include "facet/runtime/material_instance.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/png.h"

namespace {

using namespace facet::runtime;

// The app's own context, as its windowing code would have made it.
struct AppEgl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;

  bool create(std::string* error) {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay) display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr) || !eglBindAPI(EGL_OPENGL_ES_API)) {
      *error = "no EGL surfaceless display with OpenGL ES";
      return false;
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
      *error = "cannot create and make current an OpenGL ES 3.0 context";
      return false;
    }
    return true;
  }
  ~AppEgl() {
    if (context == EGL_NO_CONTEXT) return;
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
  }
};

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

int fail(const std::string& message) {
  std::fprintf(stderr, "facet-app-gl-example: error: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) return fail("usage: facet-app-gl-example <red_plastic.matpkg> <out.png>");
  std::string error;
  AppEgl egl;
  if (!egl.create(&error)) return fail(error);

  // The runtime on the app's current context: every GL entry point through the app's loader.
  GlAppContext app;
  app.getProcAddress = [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); };
  app.currentContext = eglGetCurrentContext;
  GlOptions options;
  options.readBackHdr = false;  // the mobile path: HDR and depth invalidated, never stored
  auto renderer = createGlBackend(app, options, &error);
  if (!renderer) return fail(error);

  std::vector<uint8_t> packageBytes;
  {
    std::ifstream in(argv[1], std::ios::binary);
    packageBytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) return fail(std::string("cannot read ") + argv[1]);
  }
  auto loaded = LoadedMaterial::loadFromMemory(packageBytes, argv[1], &error);
  if (!loaded) return fail(error);
  auto material = Material::create(std::move(*loaded), {"high", true, 0}, &error);
  if (!material) return fail(error);
  auto glossy = material->createInstance();
  auto rough = material->createInstance();
  const auto roughness = material->parameter("roughness");
  if (!roughness) return fail("the material has no 'roughness' parameter");
  if (!glossy->setParameter(*roughness, 0.15f, &error) ||
      !rough->setParameter("baseColor", std::array<float, 3>{0.1f, 0.35f, 0.8f}, &error) ||
      !rough->setParameter(*roughness, 0.7f, &error)) {
    return fail(error);
  }

  // Camera, sun and a constant sky, pre-exposed (docs/lighting-units.md).
  const uint32_t width = 480, height = 240;
  const double exposure = exposureFromEv100(ev100(16, 1.0 / 125, 100));
  FrameDesc frame;
  frame.width = width;
  frame.height = height;
  const glm::vec3 eye(0, 0.4f, 6);
  const glm::mat4 viewProjection = glm::perspective(glm::radians(30.0f), float(width) / height, 0.1f, 100.0f) *
                                   glm::lookAt(eye, glm::vec3(0), glm::vec3(0, 1, 0));
  std::memcpy(frame.frame.viewProjection, glm::value_ptr(viewProjection), sizeof frame.frame.viewProjection);
  store(frame.frame.cameraPosition, eye, 1);
  store(frame.frame.lightDirection, glm::normalize(glm::vec3(0.4f, 0.55f, 0.73f)));
  store(frame.frame.lightColor, glm::vec3(1, 0.96f, 0.9f) * float(110000 * exposure));
  Scene sky;  // only its sky is read: a constant environment of 6000 cd/m²
  sky.skyLuminance = 6000;
  auto lighting = buildEnvironmentLighting(sky, exposure, &error);
  if (!lighting) return fail(error);
  for (size_t k = 0; k < facet::abi::kShCoefficients; ++k)
    for (size_t c = 0; c < 3; ++c) frame.frame.sh[k][c] = lighting->sh[k][c];
  for (int c = 0; c < 3; ++c) frame.clearColor[c] = lighting->meanRadiance[size_t(c)];
  const Texture environment = environmentTexture(*lighting);
  frame.frameTextures.push_back({facet::abi::kEnvironmentBinding, facet::abi::kEnvironmentName, &environment});
  frame.frameTextures.push_back({facet::abi::kDfgLutBinding, facet::abi::kDfgLutName, &dfgTexture()});

  const Mesh sphere = makeSphere();
  const int kFrames = 4;
  FrameResult result;
  for (int i = 0; i < kFrames; ++i) {
    if (!rough->setParameter(*roughness, 0.55f + 0.05f * float(i), &error)) return fail(error);
    frame.draws = {glossy->draw(sphere, modelAt(-1.15f)), rough->draw(sphere, modelAt(1.15f))};
    if (!renderer->render(frame, &result, &error)) return fail(error);
  }
  const ResourceCounts counts = renderer->resources();
  std::printf("%d frames %ux%u on the app's %s context: %zu mesh buffer(s), %zu material block(s), %llu block upload(s)\n",
              kFrames, width, height, renderer->name(), counts.meshBuffers, counts.materialBuffers,
              static_cast<unsigned long long>(counts.materialUploads));
  if (counts.meshBuffers != 1 || counts.materialBuffers != 2 || counts.materialUploads != uint64_t(2 + kFrames - 1)) {
    return fail("unexpected GPU resource counts");
  }
  if (!writePng(argv[2], width, height, result.ldr, &error)) return fail(error);
  // The glossy instance is red, the rough one blue (centres about 88 pixels either side).
  const auto at = [&](uint32_t x, uint32_t y) { return &result.ldr[(size_t(y) * width + x) * 4]; };
  const uint8_t* left = at(width / 2 - 88, height / 2);
  const uint8_t* right = at(width / 2 + 88, height / 2);
  if (!(left[0] > left[2] + 64 && right[2] > right[0] + 64)) return fail("the two instances did not draw as set");
  renderer.reset();  // with the app's context still current, as the backend requires
  std::printf("wrote %s\n", argv[2]);
  return 0;
}
