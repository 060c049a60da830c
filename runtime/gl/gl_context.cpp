#include "gl_context.h"

#include <algorithm>
#include <cstring>

namespace facet::runtime::gl {
namespace {

// A shader that loops on an error would otherwise grow the list without bound.
constexpr size_t kMaxDebugErrors = 256;

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

std::unique_ptr<Context> Context::create(std::unique_ptr<GlContext> host, std::string* error) {
  if (!host) {
    if (error) *error = "no GL context given";
    return nullptr;
  }
  std::unique_ptr<Context> context(new Context());
  context->host_ = std::move(host);
  GlContext& h = *context->host_;
  if (!context->functions_.load([&h](const char* name) { return h.getProcAddress(name); }, error) ||
      !context->makeCurrent(error) || !context->queryCapabilities(error)) {
    return nullptr;
  }
  return context;
}

bool Context::queryCapabilities(std::string* error) {
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  if (!version) {
    if (error) *error = "glGetString(GL_VERSION) returned nothing: is the GL context current?";
    return false;
  }
  // "OpenGL ES 3.2 Mesa 22.3.6" on GLES; a desktop version string starts with its number.
  constexpr const char kEsPrefix[] = "OpenGL ES ";
  es_ = std::strncmp(version, kEsPrefix, sizeof kEsPrefix - 1) == 0;
  if (es_ && version[sizeof kEsPrefix - 1] < '3') {
    if (error) *error = std::string("the GL context is not OpenGL ES 3.x (GL_VERSION '") + version + "')";
    return false;
  }
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
      *error = "GL context (" + std::string(renderer ? renderer : "unknown renderer") + ", " + std::to_string(major_) +
               "." + std::to_string(minor_) + ") lacks GL_ARB_ES3_compatibility; GLSL ES 3.00 shaders cannot run";
    }
    return false;
  }
  // glInvalidateFramebuffer: core in ES 3.0 and GL 4.3. Debug output: core in ES 3.2, GL 4.3.
  const bool atLeast43 = !es_ && (major_ > 4 || (major_ == 4 && minor_ >= 3));
  const bool atLeastEs32 = es_ && (major_ > 3 || (major_ == 3 && minor_ >= 2));
  canInvalidate_ = es_ || atLeast43 || hasExtension("GL_ARB_invalidate_subdata");
  if (host_->backendOwnsDebugOutput() && (atLeast43 || atLeastEs32 || hasExtension("GL_KHR_debug"))) {
    // GL_KHR_debug on GLES names its functions with the KHR suffix; desktop and ES 3.2 do not.
    enableDebugOutput(es_ && !atLeastEs32);
  }
  queryResult64_ = reinterpret_cast<QueryResult64>(
      host_->getProcAddress(es_ ? "glGetQueryObjectui64vEXT" : "glGetQueryObjectui64v"));
  // Asked for by version: EGL's getProcAddress may return an entry point the context cannot run.
  if (atLeast43 || (es_ && (major_ > 3 || (major_ == 3 && minor_ >= 1)))) {
    resourceQueries_.index =
        reinterpret_cast<PFNGLGETPROGRAMRESOURCEINDEXPROC>(host_->getProcAddress("glGetProgramResourceIndex"));
    resourceQueries_.values =
        reinterpret_cast<PFNGLGETPROGRAMRESOURCEIVPROC>(host_->getProcAddress("glGetProgramResourceiv"));
  }
  if (es_ && hasExtension("GL_EXT_multisampled_render_to_texture")) {
    renderToTexture_.framebufferTexture2D = reinterpret_cast<decltype(renderToTexture_.framebufferTexture2D)>(
        host_->getProcAddress("glFramebufferTexture2DMultisampleEXT"));
    renderToTexture_.renderbufferStorage = reinterpret_cast<decltype(renderToTexture_.renderbufferStorage)>(
        host_->getProcAddress("glRenderbufferStorageMultisampleEXT"));
  }
  return checkGlError("context creation", error);
}

Context::~Context() {
  // gl_api.h's names must not keep pointing at a table that is gone.
  if (detail::current == &functions_) detail::current = &Functions::noContext();
}

bool Context::makeCurrent(std::string* error) {
  if (!host_->makeCurrent(error)) {
    detail::current = &Functions::noContext();  // whatever is current is not ours to draw into
    return false;
  }
  detail::current = &functions_;
  return true;
}

bool Context::hasExtension(const char* name) const {
  return std::find(extensions_.begin(), extensions_.end(), name) != extensions_.end();
}

void Context::enableDebugOutput(bool khrSuffix) {
  const auto callback = reinterpret_cast<PFNGLDEBUGMESSAGECALLBACKPROC>(
      host_->getProcAddress(khrSuffix ? "glDebugMessageCallbackKHR" : "glDebugMessageCallback"));
  const auto control = reinterpret_cast<PFNGLDEBUGMESSAGECONTROLPROC>(
      host_->getProcAddress(khrSuffix ? "glDebugMessageControlKHR" : "glDebugMessageControl"));
  if (!callback || !control) return;
  // OSMesa cannot request a debug context, but Mesa honours GL_DEBUG_OUTPUT on any context.
  // Synchronous delivery runs the callback inside the offending call, on this thread, so the
  // message list needs no lock and a message belongs to the frame that caused it.
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  callback(&Context::onDebugMessage, this);
  // Low-severity messages are off by default; errors can be reported at any severity.
  control(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
  debugOutput_ = glIsEnabled(GL_DEBUG_OUTPUT) == GL_TRUE;
}

void APIENTRY Context::onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                      const GLchar* message, const void* user) {
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
