// An engine's view of Facet on OpenGL ES: the app owns its GLES 3 context (here an EGL surfaceless
// one, where a phone app would have its window's), makes it current, and hands the runtime its
// getProcAddress. Then as examples/app does on Vulkan: one package loaded from memory, two
// instances of its material with different parameters, a few frames drawn into the app's own
// framebuffer (an RGBA8 texture it could sample or present) with renderToFramebuffer, nothing read
// back by the runtime. The app reads its texture back itself for the PNG, as a screenshot would.
// It links facet_runtime_core and facet_runtime_gl, and EGL for its own context: no OSMesa, no GL
// library of the runtime's, no Vulkan, no scene reader (ctest example_app_gl_link_weight).
//
//   facet-app-gl-example <red_plastic.matpkg> <out.png>
//
// Exit status 1 on any error.
#include <EGL/egl.h>
#include <EGL/eglext.h>
// Types and enums only: the app calls GL through eglGetProcAddress like the runtime, so it links
// no libGLESv2 (ctest example_app_gl_link_weight).
#define GL_GLES_PROTOTYPES 0
#include <GLES3/gl3.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "example_content.h"
#include "facet/runtime/gl_backend.h"
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

// The few GL calls the app makes itself: its render target, and the screenshot.
struct AppGl {
  PFNGLGENTEXTURESPROC genTextures = nullptr;
  PFNGLBINDTEXTUREPROC bindTexture = nullptr;
  PFNGLTEXSTORAGE2DPROC texStorage2D = nullptr;
  PFNGLDELETETEXTURESPROC deleteTextures = nullptr;
  PFNGLGENFRAMEBUFFERSPROC genFramebuffers = nullptr;
  PFNGLBINDFRAMEBUFFERPROC bindFramebuffer = nullptr;
  PFNGLFRAMEBUFFERTEXTURE2DPROC framebufferTexture2D = nullptr;
  PFNGLDELETEFRAMEBUFFERSPROC deleteFramebuffers = nullptr;
  PFNGLPIXELSTOREIPROC pixelStorei = nullptr;
  PFNGLREADPIXELSPROC readPixels = nullptr;

  bool load(std::string* error) {
    bool ok = true;
    const auto get = [&](auto& function, const char* name) {
      function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(eglGetProcAddress(name));
      if (!function) {
        *error = std::string("eglGetProcAddress resolves no ") + name;
        ok = false;
      }
    };
    get(genTextures, "glGenTextures");
    get(bindTexture, "glBindTexture");
    get(texStorage2D, "glTexStorage2D");
    get(deleteTextures, "glDeleteTextures");
    get(genFramebuffers, "glGenFramebuffers");
    get(bindFramebuffer, "glBindFramebuffer");
    get(framebufferTexture2D, "glFramebufferTexture2D");
    get(deleteFramebuffers, "glDeleteFramebuffers");
    get(pixelStorei, "glPixelStorei");
    get(readPixels, "glReadPixels");
    return ok;
  }
};

// The app's render target: an RGBA8 texture behind a framebuffer object.
struct AppTarget {
  const AppGl& gl;
  GLuint texture = 0;
  GLuint framebuffer = 0;

  AppTarget(const AppGl& functions, uint32_t width, uint32_t height) : gl(functions) {
    gl.genTextures(1, &texture);
    gl.bindTexture(GL_TEXTURE_2D, texture);
    gl.texStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, GLsizei(width), GLsizei(height));
    gl.bindTexture(GL_TEXTURE_2D, 0);
    gl.genFramebuffers(1, &framebuffer);
    gl.bindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.framebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    gl.bindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  ~AppTarget() {
    gl.deleteFramebuffers(1, &framebuffer);
    gl.deleteTextures(1, &texture);
  }

  // RGBA8 with the top row first (GL's first row is the bottom), what writePng expects.
  std::vector<uint8_t> read(uint32_t width, uint32_t height) const {
    std::vector<uint8_t> bottomUp(size_t{width} * height * 4), topDown(bottomUp.size());
    gl.bindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    gl.pixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.readPixels(0, 0, GLsizei(width), GLsizei(height), GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    const size_t row = size_t{width} * 4;
    for (uint32_t y = 0; y < height; ++y) {
      std::copy_n(bottomUp.begin() + std::ptrdiff_t((height - 1 - y) * row), row,
                  topDown.begin() + std::ptrdiff_t(y * row));
    }
    return topDown;
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

  // The same material, instances and frame as examples/app (example_content.h), drawn into the
  // app's framebuffer.
  facet::example::ExampleContent content;
  if (!content.create(argv[1], &error)) return fail(error);
  AppGl gl;
  if (!gl.load(&error)) return fail(error);
  const uint32_t width = content.kWidth, height = content.kHeight;
  std::vector<uint8_t> pixels;
  {
    AppTarget target(gl, width, height);
    for (int i = 0; i < content.kFrames; ++i) {
      if (!content.animate(i, &error) ||
          !renderer->renderToFramebuffer(content.frame, GlAppTarget{target.framebuffer, width, height}, &error)) {
        return fail(error);
      }
    }
    pixels = target.read(width, height);
  }
  if (std::string wrong = content.checkResources(renderer->resources()); !wrong.empty()) return fail(wrong);
  if (!writePng(argv[2], width, height, pixels, &error)) return fail(error);
  if (std::string wrong = content.checkInstances(pixels); !wrong.empty()) return fail(wrong);
  renderer.reset();  // with the app's context still current, as the backend requires
  std::printf("wrote %s\n", argv[2]);
  return 0;
}
