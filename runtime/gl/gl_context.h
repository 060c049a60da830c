// An offscreen GL context, with debug output collected: a real OpenGL ES 3.x context through EGL
// on Mesa's surfaceless platform (what a phone gives), or an OpenGL core context on OSMesa
// (llvmpipe) that accepts "#version 300 es" shaders, where EGL is missing. Both run on the same
// gl* entry points: libOSMesa's exports dispatch through Mesa's shared glapi to whichever context
// is current, EGL's included (checked on these machines, Mesa 22.3).
#pragma once

// gl_api.h first: osmesa.h includes GL/gl.h, and GL/glext.h (included once) must see
// GL_GLEXT_PROTOTYPES on that first inclusion.
#include "gl_api.h"

#include <GL/osmesa.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace facet::runtime::gl {

enum class ContextKind {
  Auto,    // EGL GLES when available, else OSMesa
  EglGles, // OpenGL ES 3.2 (3.0 if refused), EGL surfaceless
  OsMesa,  // OpenGL 4.5 core (3.3 if refused) with ARB_ES3_compatibility
  AppCurrent,  // the app's OpenGL ES 3.x context, current (through EGL) when created: adopted, not owned
};

class Context {
 public:
  // Returns nullptr and sets *error when the kind asked for is unavailable (for OSMesa: also
  // when ARB_ES3_compatibility is missing).
  static std::unique_ptr<Context> create(ContextKind kind, std::string* error);
  ~Context();

  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // OSMesa has one current context per thread and every backend owns its own, so each entry
  // point that issues GL calls makes this one current first.
  bool makeCurrent(std::string* error);

  bool isEs() const { return es_; }
  const char* kindName() const { return es_ ? "EGL GLES" : "OSMesa GL core"; }
  int majorVersion() const { return major_; }
  int minorVersion() const { return minor_; }
  bool hasExtension(const char* name) const;
  // glInvalidateFramebuffer: core in 4.3, ARB_invalidate_subdata before.
  bool canInvalidateFramebuffer() const { return canInvalidate_; }
  // The 64-bit query result getter (glGetQueryObjectui64v, or its EXT name on GLES), which
  // libOSMesa does not export: resolved through the context's GetProcAddress. Null if absent.
  using QueryResult64 = void(APIENTRY*)(GLuint id, GLenum pname, GLuint64* value);
  QueryResult64 queryResult64() const { return queryResult64_; }
  // True when glDebugMessageCallback is installed and debug output is enabled.
  bool debugOutputEnabled() const { return debugOutput_; }
  // Debug messages of type error or severity high, formatted one per entry.
  const std::vector<std::string>& debugErrors() const { return debugErrors_; }

 private:
  Context() = default;
  bool initialiseOsMesa(std::string* error);
  bool initialiseEgl(std::string* error);
  bool adoptCurrentEgl(std::string* error);
  bool queryCapabilities(std::string* error);
  void enableDebugOutput();
  static void APIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                                      GLsizei length, const GLchar* message, const void* user);

  bool es_ = false;
  OSMesaContext context_ = nullptr;
  void* eglDisplay_ = nullptr;  // EGLDisplay / EGLContext, kept opaque so EGL stays optional
  void* eglContext_ = nullptr;
  bool adopted_ = false;  // the app's context: checked to be current, never made current or destroyed
  // OSMesaMakeCurrent requires a colour buffer; the backend renders into its own framebuffer
  // objects, so the default framebuffer only needs to exist.
  static constexpr int kDummySize = 4;
  uint8_t dummyBuffer_[kDummySize * kDummySize * 4] = {};
  int major_ = 0;
  int minor_ = 0;
  bool canInvalidate_ = false;
  bool debugOutput_ = false;
  QueryResult64 queryResult64_ = nullptr;
  std::vector<std::string> extensions_;
  std::vector<std::string> debugErrors_;
};

}  // namespace facet::runtime::gl
