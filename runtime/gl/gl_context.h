// The backend's view of its GL context: the entry-point table loaded through the context's
// getProcAddress (gl_api.h), what the context can do, and the debug output collected when the
// backend owns it. Who created the context (the app, or facet_runtime_gl_headless's EGL and
// OSMesa for tests) is behind facet::runtime::GlContext.
#pragma once

#include "gl_api.h"

#include <memory>
#include <string>
#include <vector>

#include "facet/runtime/gl_backend.h"

namespace facet::runtime::gl {

class Context {
 public:
  // Makes `host` current, loads its entry points and checks it can run GLSL ES 3.00. Returns
  // nullptr and sets *error otherwise.
  static std::unique_ptr<Context> create(std::unique_ptr<GlContext> host, std::string* error);
  ~Context();

  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Every entry point that issues GL calls makes (or checks) the context current first, which also
  // points gl_api.h's names at this context's table.
  bool makeCurrent(std::string* error);

  bool isEs() const { return es_; }
  const char* kindName() const { return host_->name(); }
  int majorVersion() const { return major_; }
  int minorVersion() const { return minor_; }
  bool hasExtension(const char* name) const;
  // glInvalidateFramebuffer: core in 4.3, ARB_invalidate_subdata before.
  bool canInvalidateFramebuffer() const { return canInvalidate_; }
  // The 64-bit query result getter (glGetQueryObjectui64v, or its EXT name on GLES), outside
  // the required table because GLES 3.0 lacks it. Null if absent.
  using QueryResult64 = PFNGLGETQUERYOBJECTUI64VPROC;
  QueryResult64 queryResult64() const { return queryResult64_; }
  // Program interface queries (GLES 3.1, GL 4.3): which stages reference a uniform, for the
  // messages of the interface check (gl_reflection.h). Outside the required table because GLES
  // 3.0 lacks them; both null unless the context's version has them.
  struct ResourceQueries {
    PFNGLGETPROGRAMRESOURCEINDEXPROC index = nullptr;
    PFNGLGETPROGRAMRESOURCEIVPROC values = nullptr;
  };
  const ResourceQueries& resourceQueries() const { return resourceQueries_; }
  // GL_EXT_multisampled_render_to_texture (GLES): a single-sample texture attached for rendering
  // with N samples, which the driver keeps and resolves on the tile flush (the mobile form of
  // MSAA). Outside the required table (an extension); both null unless the context lists it.
  struct RenderToTexture {
    void(APIENTRYP framebufferTexture2D)(GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                                         GLint level, GLsizei samples) = nullptr;
    void(APIENTRYP renderbufferStorage)(GLenum target, GLsizei samples, GLenum internalformat, GLsizei width,
                                        GLsizei height) = nullptr;
    bool present() const { return framebufferTexture2D && renderbufferStorage; }
  };
  const RenderToTexture& renderToTexture() const { return renderToTexture_; }
  // True when glDebugMessageCallback is installed and debug output is enabled.
  bool debugOutputEnabled() const { return debugOutput_; }
  // Debug messages of type error or severity high, formatted one per entry.
  const std::vector<std::string>& debugErrors() const { return debugErrors_; }

 private:
  Context() = default;
  bool queryCapabilities(std::string* error);
  void enableDebugOutput(bool khrSuffix);
  static void APIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                      const GLchar* message, const void* user);

  std::unique_ptr<GlContext> host_;
  Functions functions_;
  bool es_ = false;
  int major_ = 0;
  int minor_ = 0;
  bool canInvalidate_ = false;
  bool debugOutput_ = false;
  QueryResult64 queryResult64_ = nullptr;
  ResourceQueries resourceQueries_;
  RenderToTexture renderToTexture_;
  std::vector<std::string> extensions_;
  std::vector<std::string> debugErrors_;
};

}  // namespace facet::runtime::gl
