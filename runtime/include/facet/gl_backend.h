// The GL backend on a context someone else owns (facet_runtime_gl): the app's current OpenGL ES
// 3.0+ context, reached through the app's own getProcAddress. facet_runtime_gl links no GL, EGL
// or OSMesa library: every entry point it calls comes from that function.
//
//   // the app's context is current on this thread (EGL, SDL, GLFW, Android's GLSurfaceView ...)
//   facet::runtime::GlAppContext app;
//   app.getProcAddress = [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); };
//   app.currentContext = eglGetCurrentContext;  // optional: lets render() refuse another context
//   auto renderer = facet::runtime::createGlBackend(app, facet::runtime::GlOptions{}, &error);
//
// Headless contexts of the backend's own (EGL surfaceless, OSMesa) are the tests' and the
// viewer's: createGlBackend(const GlOptions&, ...) in render_backend.h, from facet_runtime_gl_headless.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "facet/render_backend.h"

namespace facet::runtime {

// A GL context as the backend sees it. An engine that switches contexts itself may implement it;
// GlAppContext below covers the usual case of one context current when the backend runs.
class GlContext {
 public:
  virtual ~GlContext() = default;
  // The address of a GL entry point ("glGenBuffers", or an extension's "glGetQueryObjectui64vEXT"),
  // or null.
  virtual void* getProcAddress(const char* name) = 0;
  // Makes the context current on the calling thread (one the backend owns) or checks that it is
  // (the app's). Called before every entry point that issues GL calls, including destruction.
  virtual bool makeCurrent(std::string* error) = 0;
  virtual const char* name() const = 0;  // "EGL GLES", "OSMesa GL core", "app GL"
  // True when the backend may install its own GL debug callback (validationErrors()); the app's
  // context keeps the app's callback, if it has one.
  virtual bool backendOwnsDebugOutput() const = 0;
};

// The app's context, current on the calling thread whenever the backend is created, renders or
// is destroyed. It must be OpenGL ES 3.x, or desktop GL with GL_ARB_ES3_compatibility (the GLSL ES
// 3.00 shaders). The backend never switches contexts and never destroys the app's.
struct GlAppContext {
  // Required: eglGetProcAddress (through a cast), SDL_GL_GetProcAddress, glfwGetProcAddress (cast).
  std::function<void*(const char* name)> getProcAddress;
  // Optional: the handle of the context current on the calling thread (eglGetCurrentContext,
  // SDL_GL_GetCurrentContext). When given, the handle at creation is remembered and render()
  // fails, drawing nothing, while another context is current.
  std::function<void*()> currentContext;
};

std::unique_ptr<GlContext> adoptGlContext(GlAppContext app, std::string* error);

// Each returns nullptr and sets *error when the context is unusable (not current, not GLES 3,
// an entry point that does not resolve). GlOptions::context is not read: the context is given.
std::unique_ptr<RenderBackend> createGlBackend(const GlAppContext& app, const GlOptions& options, std::string* error);
std::unique_ptr<RenderBackend> createGlBackend(std::unique_ptr<GlContext> context, const GlOptions& options,
                                               std::string* error);

}  // namespace facet::runtime
