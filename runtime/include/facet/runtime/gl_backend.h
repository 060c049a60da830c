// The GL backend on a context someone else owns (facet_runtime_gl): the app's current OpenGL ES
// 3.0+ context, reached through the app's own getProcAddress. facet_runtime_gl links no GL, EGL
// or OSMesa library: every entry point it calls comes from that function.
//
//   // the app's context is current on this thread (EGL, SDL, GLFW, Android's GLSurfaceView ...)
//   facet::runtime::GlAppContext app;
//   app.getProcAddress = [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); };
//   app.currentContext = eglGetCurrentContext;  // optional: lets render() refuse another context
//   auto renderer = facet::runtime::createGlBackend(app, facet::runtime::GlOptions{}, &error);
//   renderer->renderToFramebuffer(frame, facet::runtime::GlAppTarget{appFbo, width, height}, &error);
//
// Headless contexts of the backend's own (EGL surfaceless, OSMesa) are the tests' and the
// viewer's: createGlBackend(const GlOptions&, ...) in render_backend.h, from facet_runtime_gl_headless.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "facet/runtime/render_backend.h"

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

// The app's framebuffer a frame's tone-mapped, sRGB-encoded result is drawn into: a framebuffer
// object of the app's context (0: the default framebuffer, the window's surface), complete, with
// width × height the frame's size. The post pass writes its draw buffer 0 (GL_COLOR_ATTACHMENT0
// unless the app changed glDrawBuffers; GL_BACK for the default framebuffer), which must be
// unsigned-normalised and linear-encoded (GL_RGBA8, GL_RGB8: an sRGB attachment would encode the
// already encoded bytes a second time). An app that wants the image as a texture attaches its
// RGBA8 texture to its FBO. How the two render paths use it (docs/runtime.md "The app's framebuffer"):
// - separate: the post pass draws into the app's framebuffer, sampling the stored HDR texture;
// - merged: the app's attachment (a 2D texture level, a cube face, or a renderbuffer) becomes
//   colour 1 of the backend's framebuffer-fetch framebuffer for this call, so HDR and depth stay
//   in tile memory and the post pass writes the app's image itself; detached before returning
//   (the backend keeps no reference to it). The default framebuffer cannot be attached: frames
//   into it run the separate path (the backend builds both post programs for that).
struct GlAppTarget {
  uint32_t framebuffer = 0;  // a GLuint FBO name, or 0
  uint32_t width = 0;
  uint32_t height = 0;
};

// The GL backend an app creates on its context. GL state on return from renderToFramebuffer (and
// render(), with framebuffer 0 bound): the target framebuffer bound to GL_FRAMEBUFFER (draw and
// read), viewport (0, 0, width, height), program 0, vertex array 0, and GL_BLEND, GL_DEPTH_TEST,
// GL_CULL_FACE, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_POLYGON_OFFSET_FILL, GL_RASTERIZER_DISCARD,
// GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_COVERAGE disabled, depth and colour masks all true,
// GL_PIXEL_UNPACK_BUFFER and GL_PIXEL_PACK_BUFFER 0, pack and unpack row lengths and skips 0.
// Changed and not restored (the app sets them before relying on them): texture bindings of units
// 0..15 and the active unit, GL_UNIFORM_BUFFER bindings (generic and 0..3), GL_ARRAY_BUFFER,
// blend function, depth function, front face, cull face mode, GL_UNPACK_ALIGNMENT,
// GL_RENDERBUFFER binding. Nothing is restored because an engine re-binds its own state per pass
// anyway, and glGet* round trips stall multi-threaded drivers. After a failed call the state is
// unspecified (the app re-binds what it uses; its context and objects are untouched).
class GlRenderer : public RenderBackend {
 public:
  // Renders the frame into the app's framebuffer instead of reading it back: nothing is read
  // back, and the call does not wait for the GPU (the app's own swap, fence or glReadPixels
  // orders later work as for any GL draw). Not timed (FrameResult::gpuTimes is render()'s), and
  // HDR is not read back (GlOptions::readBackHdr is render()'s): merged, it is invalidated.
  // A target that is not usable (size 0 or not the frame's, not a framebuffer of this context,
  // incomplete, sRGB or non-normalised draw buffer 0) is an error naming why, drawing nothing.
  virtual bool renderToFramebuffer(const FrameDesc& frame, const GlAppTarget& target, std::string* error) = 0;
};

// Each returns nullptr and sets *error when the context is unusable (not current, not GLES 3,
// an entry point that does not resolve). GlOptions::context is not read: the context is given.
std::unique_ptr<GlRenderer> createGlBackend(const GlAppContext& app, const GlOptions& options, std::string* error);
std::unique_ptr<GlRenderer> createGlBackend(std::unique_ptr<GlContext> context, const GlOptions& options,
                                            std::string* error);

}  // namespace facet::runtime
