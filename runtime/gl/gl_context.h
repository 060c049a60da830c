// An offscreen OpenGL core context on Mesa's OSMesa (llvmpipe), with debug output collected.
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

class Context {
 public:
  // A 4.5 core context (3.3 core if 4.5 is refused) that accepts "#version 300 es" shaders.
  // Returns nullptr and sets *error when OSMesa or ARB_ES3_compatibility is unavailable.
  static std::unique_ptr<Context> create(std::string* error);
  ~Context();

  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // OSMesa has one current context per thread and every backend owns its own, so each entry
  // point that issues GL calls makes this one current first.
  bool makeCurrent(std::string* error);

  int majorVersion() const { return major_; }
  int minorVersion() const { return minor_; }
  bool hasExtension(const char* name) const;
  // glInvalidateFramebuffer: core in 4.3, ARB_invalidate_subdata before.
  bool canInvalidateFramebuffer() const { return canInvalidate_; }
  // True when glDebugMessageCallback is installed and debug output is enabled.
  bool debugOutputEnabled() const { return debugOutput_; }
  // Debug messages of type error or severity high, formatted one per entry.
  const std::vector<std::string>& debugErrors() const { return debugErrors_; }

 private:
  Context() = default;
  bool initialise(std::string* error);
  void enableDebugOutput();
  static void APIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                                      GLsizei length, const GLchar* message, const void* user);

  OSMesaContext context_ = nullptr;
  // OSMesaMakeCurrent requires a colour buffer; the backend renders into its own framebuffer
  // objects, so the default framebuffer only needs to exist.
  static constexpr int kDummySize = 4;
  uint8_t dummyBuffer_[kDummySize * kDummySize * 4] = {};
  int major_ = 0;
  int minor_ = 0;
  bool canInvalidate_ = false;
  bool debugOutput_ = false;
  std::vector<std::string> extensions_;
  std::vector<std::string> debugErrors_;
};

}  // namespace facet::runtime::gl
