#include "gl_context.h"

#include <algorithm>

#if defined(FACET_HAVE_EGL)
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif

namespace facet::runtime::gl {
namespace {

// A shader that loops on an error would otherwise grow the list without bound.
constexpr size_t kMaxDebugErrors = 256;

// The context this code made current last on this thread (see Context::makeCurrent).
thread_local const Context* currentContext = nullptr;

OSMesaContext createOsMesaContext(int major, int minor) {
  const int attributes[] = {
      OSMESA_FORMAT, OSMESA_RGBA,
      OSMESA_DEPTH_BITS, 0,  // depth lives in the backend's own renderbuffer
      OSMESA_STENCIL_BITS, 0,
      OSMESA_ACCUM_BITS, 0,
      OSMESA_PROFILE, OSMESA_CORE_PROFILE,
      OSMESA_CONTEXT_MAJOR_VERSION, major,
      OSMESA_CONTEXT_MINOR_VERSION, minor,
      0,
  };
  return OSMesaCreateContextAttribs(attributes, nullptr);
}

const char* debugSourceName(GLenum source) {
  switch (source) {
    case GL_DEBUG_SOURCE_API: return "api";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
    case GL_DEBUG_SOURCE_APPLICATION: return "application";
    default: return "other";
  }
}

}  // namespace

std::unique_ptr<Context> Context::create(ContextKind kind, std::string* error) {
  if (kind == ContextKind::AppCurrent) {
    std::unique_ptr<Context> context(new Context());
    std::string why;
    if (context->adoptCurrentEgl(&why)) return context;
    if (error) *error = why;
    return nullptr;
  }
  std::string eglError;
  if (kind != ContextKind::OsMesa) {
    std::unique_ptr<Context> context(new Context());
    if (context->initialiseEgl(&eglError)) return context;
    if (kind == ContextKind::EglGles) {
      if (error) *error = eglError;
      return nullptr;
    }
  }
  std::unique_ptr<Context> context(new Context());
  if (!context->initialiseOsMesa(error)) {
    if (error && !eglError.empty()) *error += " (and EGL: " + eglError + ")";
    return nullptr;
  }
  return context;
}

bool Context::initialiseOsMesa(std::string* error) {
  context_ = createOsMesaContext(4, 5);
  if (!context_) context_ = createOsMesaContext(3, 3);
  if (!context_) {
    if (error) *error = "OSMesa refused to create a GL 4.5 or 3.3 core context";
    return false;
  }
  return makeCurrent(error) && queryCapabilities(error);
}

bool Context::initialiseEgl(std::string* error) {
#if defined(FACET_HAVE_EGL)
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) {
    *error = "EGL has no eglGetPlatformDisplayEXT";
    return false;
  }
  EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
    *error = "EGL surfaceless platform (EGL_MESA_platform_surfaceless) is unavailable";
    return false;
  }
  eglDisplay_ = display;
  if (!eglBindAPI(EGL_OPENGL_ES_API)) {
    *error = "EGL cannot bind the OpenGL ES API";
    return false;
  }
  // Surfaceless: no config is needed (EGL_KHR_no_config_context), the backend renders into its
  // own framebuffer objects.
  EGLContext context = EGL_NO_CONTEXT;
  for (EGLint wantMinor : {2, 0}) {
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, wantMinor, EGL_NONE};
    context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context != EGL_NO_CONTEXT) break;
  }
  if (context == EGL_NO_CONTEXT) {
    *error = "EGL refused an OpenGL ES 3.2 or 3.0 context";
    return false;
  }
  eglContext_ = context;
  es_ = true;
  return makeCurrent(error) && queryCapabilities(error);
#else
  *error = "built without EGL";
  return false;
#endif
}

// The app's context as it is: no API is bound, no context created or made current. It must be an
// OpenGL ES 3.x context (the GLSL ES 3.00 shaders and the ES entry points the backend uses).
bool Context::adoptCurrentEgl(std::string* error) {
#if defined(FACET_HAVE_EGL)
  adopted_ = true;
  eglDisplay_ = eglGetCurrentDisplay();
  eglContext_ = eglGetCurrentContext();
  if (eglContext_ == EGL_NO_CONTEXT) {
    *error = "no EGL context is current on this thread: make the app's OpenGL ES 3 context current first";
    return false;
  }
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  if (!version || std::string(version).rfind("OpenGL ES 3", 0) != 0) {
    *error = std::string("the current context is not OpenGL ES 3.x (GL_VERSION '") + (version ? version : "none") + "')";
    return false;
  }
  es_ = true;
  currentContext = this;
  return queryCapabilities(error);
#else
  *error = "built without EGL: the app's current context cannot be adopted";
  return false;
#endif
}

bool Context::queryCapabilities(std::string* error) {
  glGetIntegerv(GL_MAJOR_VERSION, &major_);
  glGetIntegerv(GL_MINOR_VERSION, &minor_);
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (name) extensions_.emplace_back(name);
  }

  // "#version 300 es" shaders on a desktop context need ES 3.0 compatibility.
  if (!es_ && !hasExtension("GL_ARB_ES3_compatibility")) {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (error) {
      *error = "GL context (" + std::string(renderer ? renderer : "unknown renderer") + ", " +
               std::to_string(major_) + "." + std::to_string(minor_) +
               " core) lacks GL_ARB_ES3_compatibility; GLSL ES 3.00 shaders cannot run";
    }
    return false;
  }
  // glInvalidateFramebuffer: core in ES 3.0 and GL 4.3. Debug output: core in ES 3.2, GL 4.3.
  const bool atLeast43 = major_ > 4 || (major_ == 4 && minor_ >= 3);
  const bool atLeastEs32 = es_ && (major_ > 3 || (major_ == 3 && minor_ >= 2));
  canInvalidate_ = es_ || atLeast43 || hasExtension("GL_ARB_invalidate_subdata");
  // The app's context keeps the app's own debug callback, if it has one.
  if (!adopted_ && (atLeast43 || atLeastEs32 || hasExtension("GL_KHR_debug"))) enableDebugOutput();
#if defined(FACET_HAVE_EGL)
  if (es_) {
    queryResult64_ = reinterpret_cast<QueryResult64>(eglGetProcAddress("glGetQueryObjectui64vEXT"));
  }
#endif
  if (!es_) {
    queryResult64_ = reinterpret_cast<QueryResult64>(OSMesaGetProcAddress("glGetQueryObjectui64v"));
  }
  return checkGlError("context creation", error);
}

Context::~Context() {
  // Unbind first so the thread is not left pointing at a destroyed context.
  const bool current = currentContext == this;
  if (current) currentContext = nullptr;
  if (adopted_) return;  // the app's context: the app destroys it
#if defined(FACET_HAVE_EGL)
  if (eglContext_) {
    auto display = static_cast<EGLDisplay>(eglDisplay_);
    if (current) eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, static_cast<EGLContext>(eglContext_));
  }
  // The display is shared by every context of the process (eglGetPlatformDisplay returns the
  // same one): terminating it here would pull it from under other backends.
#endif
  if (!context_) return;
  if (current) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(context_);
}

// One thread may hold OSMesa and EGL contexts at once (several backends), and both drive the same
// glapi dispatch, so neither API's own idea of "current" can be trusted after the other switched
// (OSMesaGetCurrentContext even returns EGL's context). The context made current last by this
// code is tracked here instead; switching always goes through the target API.
bool Context::makeCurrent(std::string* error) {
#if defined(FACET_HAVE_EGL)
  if (adopted_) {
    // Never switched by the backend: the app makes its context current before calling it.
    if (eglGetCurrentContext() != static_cast<EGLContext>(eglContext_)) {
      if (error) *error = "the app's GL context is not current on this thread";
      return false;
    }
    currentContext = this;
    return true;
  }
#endif
  if (currentContext == this) return true;
#if defined(FACET_HAVE_EGL)
  if (es_) {
    if (!eglMakeCurrent(static_cast<EGLDisplay>(eglDisplay_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                        static_cast<EGLContext>(eglContext_))) {
      if (error) *error = "eglMakeCurrent failed";
      return false;
    }
    currentContext = this;
    return true;
  }
  if (eglGetCurrentContext() != EGL_NO_CONTEXT) {
    eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
#endif
  if (!OSMesaMakeCurrent(context_, dummyBuffer_, GL_UNSIGNED_BYTE, kDummySize, kDummySize)) {
    if (error) *error = "OSMesaMakeCurrent failed";
    return false;
  }
  currentContext = this;
  return true;
}

bool Context::hasExtension(const char* name) const {
  return std::find(extensions_.begin(), extensions_.end(), name) != extensions_.end();
}

void Context::enableDebugOutput() {
  // OSMesa cannot request a debug context, but Mesa honours GL_DEBUG_OUTPUT on any context.
  // Synchronous delivery runs the callback inside the offending call, on this thread, so the
  // message list needs no lock and a message belongs to the frame that caused it.
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(&Context::onDebugMessage, this);
  // Low-severity messages are off by default; errors can be reported at any severity.
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
  debugOutput_ = glIsEnabled(GL_DEBUG_OUTPUT) == GL_TRUE;
}

void APIENTRY Context::onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                                      GLsizei length, const GLchar* message, const void* user) {
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  // Mesa repeats a shader's compile errors here. They are not API misuse, and render() already
  // fails with the full info log, so they would only make one mistake count twice.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  auto* self = static_cast<Context*>(const_cast<void*>(user));
  if (!self || self->debugErrors_.size() >= kMaxDebugErrors) return;
  // This runs inside a C library: nothing may propagate out of it.
  try {
    std::string text = "GL debug (";
    text += debugSourceName(source);
    text += type == GL_DEBUG_TYPE_ERROR ? ", error" : ", high severity";
    text += ", id " + std::to_string(id) + "): ";
    if (message) {
      text += length >= 0 ? std::string(message, static_cast<size_t>(length)) : std::string(message);
    }
    self->debugErrors_.push_back(std::move(text));
  } catch (...) {
  }
}

}  // namespace facet::runtime::gl
