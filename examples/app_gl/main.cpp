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

#include <cstdio>
#include <memory>
#include <string>

#include "example_content.h"
#include "facet/gl_backend.h"
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

  // The same material, instances and frame as examples/app (example_content.h).
  facet::example::ExampleContent content;
  if (!content.create(argv[1], &error)) return fail(error);
  FrameResult result;
  for (int i = 0; i < content.kFrames; ++i) {
    if (!content.animate(i, &error) || !renderer->render(content.frame, &result, &error)) return fail(error);
  }
  if (std::string wrong = content.checkResources(renderer->resources()); !wrong.empty()) return fail(wrong);
  if (!writePng(argv[2], result.width, result.height, result.ldr, &error)) return fail(error);
  if (std::string wrong = content.checkInstances(result.ldr); !wrong.empty()) return fail(wrong);
  renderer.reset();  // with the app's context still current, as the backend requires
  std::printf("wrote %s\n", argv[2]);
  return 0;
}
