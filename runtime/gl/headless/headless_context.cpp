#include "headless_context.h"

#include <GL/osmesa.h>

#include <cstdint>

#include <EGL/egl.h>
#include <EGL/eglext.h>

namespace facet::runtime::gl {
namespace {

// One thread may hold OSMesa and EGL contexts at once (several backends), and both drive Mesa's
// one glapi dispatch, so neither API's own idea of "current" can be trusted after the other
// switched (OSMesaGetCurrentContext even returns EGL's context). The context made current last by
// this code is tracked here instead; switching always goes through the target API.
thread_local const GlContext* lastMadeCurrent = nullptr;

class OsMesaContext final : public GlContext {
 public:
  bool initialise(std::string* error) {
    context_ = create(4, 5);
    if (!context_) context_ = create(3, 3);
    if (!context_) {
      if (error) *error = "OSMesa refused to create a GL 4.5 or 3.3 core context";
      return false;
    }
    return makeCurrent(error);
  }
  ~OsMesaContext() override {
    if (!context_) return;
    if (lastMadeCurrent == this) {
      OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
      lastMadeCurrent = nullptr;
    }
    OSMesaDestroyContext(context_);
  }

  void* getProcAddress(const char* name) override { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }
  bool makeCurrent(std::string* error) override {
    if (lastMadeCurrent == this) return true;
    // An EGL context bound on this thread would keep its own binding alongside ours.
    if (eglGetCurrentContext() != EGL_NO_CONTEXT) {
      eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    if (!OSMesaMakeCurrent(context_, dummyBuffer_, GL_UNSIGNED_BYTE, kDummySize, kDummySize)) {
      if (error) *error = "OSMesaMakeCurrent failed";
      return false;
    }
    lastMadeCurrent = this;
    return true;
  }
  const char* name() const override { return "OSMesa GL core"; }
  bool backendOwnsDebugOutput() const override { return true; }

 private:
  static OSMesaContext create(int major, int minor) {
    const int attributes[] = {
        OSMESA_FORMAT,
        OSMESA_RGBA,
        OSMESA_DEPTH_BITS,
        0,  // depth lives in the backend's own renderbuffer
        OSMESA_STENCIL_BITS,
        0,
        OSMESA_ACCUM_BITS,
        0,
        OSMESA_PROFILE,
        OSMESA_CORE_PROFILE,
        OSMESA_CONTEXT_MAJOR_VERSION,
        major,
        OSMESA_CONTEXT_MINOR_VERSION,
        minor,
        0,
    };
    return OSMesaCreateContextAttribs(attributes, nullptr);
  }

  ::OSMesaContext context_ = nullptr;
  // OSMesaMakeCurrent requires a colour buffer; the backend renders into its own framebuffer
  // objects, so the default framebuffer only needs to exist.
  static constexpr int kDummySize = 4;
  uint8_t dummyBuffer_[kDummySize * kDummySize * 4] = {};
};

class EglContext final : public GlContext {
 public:
  bool initialise(std::string* error) {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) {
      *error = "EGL has no eglGetPlatformDisplayEXT";
      return false;
    }
    display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
      *error = "EGL surfaceless platform (EGL_MESA_platform_surfaceless) is unavailable";
      return false;
    }
    if (!eglBindAPI(EGL_OPENGL_ES_API)) {
      *error = "EGL cannot bind the OpenGL ES API";
      return false;
    }
    // Surfaceless: no config is needed (EGL_KHR_no_config_context), the backend renders into its
    // own framebuffer objects.
    for (EGLint wantMinor : {2, 0}) {
      const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, wantMinor, EGL_NONE};
      context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
      if (context_ != EGL_NO_CONTEXT) break;
    }
    if (context_ == EGL_NO_CONTEXT) {
      *error = "EGL refused an OpenGL ES 3.2 or 3.0 context";
      return false;
    }
    return makeCurrent(error);
  }
  ~EglContext() override {
    if (context_ == EGL_NO_CONTEXT) return;
    if (lastMadeCurrent == this) {
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      lastMadeCurrent = nullptr;
    }
    eglDestroyContext(display_, context_);
    // The display is shared by every context of the process (eglGetPlatformDisplay returns the
    // same one): terminating it here would pull it from under other backends.
  }

  // EGL 1.5 resolves core GL functions too (EGL_KHR_get_all_proc_addresses).
  void* getProcAddress(const char* name) override { return reinterpret_cast<void*>(eglGetProcAddress(name)); }
  bool makeCurrent(std::string* error) override {
    if (lastMadeCurrent == this) return true;
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      if (error) *error = "eglMakeCurrent failed";
      return false;
    }
    lastMadeCurrent = this;
    return true;
  }
  const char* name() const override { return "EGL GLES"; }
  bool backendOwnsDebugOutput() const override { return true; }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> createHeadlessContext(GlContextKind kind, std::string* error) {
  std::string eglError;
  if (kind != GlContextKind::OsMesa) {
    auto egl = std::make_unique<EglContext>();
    if (egl->initialise(&eglError)) return egl;
    if (kind == GlContextKind::EglGles) {
      if (error) *error = eglError;
      return nullptr;
    }
  }
  auto osmesa = std::make_unique<OsMesaContext>();
  if (!osmesa->initialise(error)) {
    if (error && !eglError.empty()) *error += " (and EGL: " + eglError + ")";
    return nullptr;
  }
  return osmesa;
}

}  // namespace facet::runtime::gl
