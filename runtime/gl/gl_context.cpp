#include "gl_context.h"

#include <algorithm>

namespace facet::runtime::gl {
namespace {

// A shader that loops on an error would otherwise grow the list without bound.
constexpr size_t kMaxDebugErrors = 256;

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

std::unique_ptr<Context> Context::create(std::string* error) {
  std::unique_ptr<Context> context(new Context());
  if (!context->initialise(error)) return nullptr;
  return context;
}

bool Context::initialise(std::string* error) {
  context_ = createOsMesaContext(4, 5);
  if (!context_) context_ = createOsMesaContext(3, 3);
  if (!context_) {
    if (error) *error = "OSMesa refused to create a GL 4.5 or 3.3 core context";
    return false;
  }
  if (!makeCurrent(error)) return false;

  glGetIntegerv(GL_MAJOR_VERSION, &major_);
  glGetIntegerv(GL_MINOR_VERSION, &minor_);
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (name) extensions_.emplace_back(name);
  }

  // "#version 300 es" shaders on a desktop context need ES 3.0 compatibility.
  if (!hasExtension("GL_ARB_ES3_compatibility")) {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (error) {
      *error = "GL context (" + std::string(renderer ? renderer : "unknown renderer") + ", " +
               std::to_string(major_) + "." + std::to_string(minor_) +
               " core) lacks GL_ARB_ES3_compatibility; GLSL ES 3.00 shaders cannot run";
    }
    return false;
  }
  const bool atLeast43 = major_ > 4 || (major_ == 4 && minor_ >= 3);
  canInvalidate_ = atLeast43 || hasExtension("GL_ARB_invalidate_subdata");
  if (atLeast43 || hasExtension("GL_KHR_debug")) enableDebugOutput();
  return checkGlError("context creation", error);
}

Context::~Context() {
  if (!context_) return;
  // Unbind first so the thread is not left pointing at a destroyed context.
  if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(context_);
}

bool Context::makeCurrent(std::string* error) {
  if (OSMesaGetCurrentContext() == context_) return true;
  if (!OSMesaMakeCurrent(context_, dummyBuffer_, GL_UNSIGNED_BYTE, kDummySize, kDummySize)) {
    if (error) *error = "OSMesaMakeCurrent failed";
    return false;
  }
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
