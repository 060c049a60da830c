#include "gl_api.h"

#include <type_traits>

namespace facet::runtime::gl {
namespace {

const char* glErrorName(GLenum code) {
  switch (code) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    default: return "unknown GL error";
  }
}

// A no-op of the same signature as a GL entry point.
template <typename F>
struct NoOp;
template <typename R, typename... Args>
struct NoOp<R(APIENTRY*)(Args...)> {
  static R APIENTRY call(Args...) { return R(); }
};
template <typename... Args>
struct NoOp<void(APIENTRY*)(Args...)> {
  static void APIENTRY call(Args...) {}
};

}  // namespace

const Functions& Functions::noContext() {
  static const Functions table = [] {
    Functions f;
    f.forEach([](auto& member, const char*) { member = &NoOp<std::remove_reference_t<decltype(member)>>::call; });
    return f;
  }();
  return table;
}

namespace detail {
thread_local const Functions* current = &Functions::noContext();
}  // namespace detail

bool Functions::load(const std::function<void*(const char*)>& getProcAddress, std::string* error) {
  std::string missing;
  forEach([&](auto& member, const char* name) {
    member = reinterpret_cast<std::remove_reference_t<decltype(member)>>(getProcAddress(name));
    if (!member) missing += missing.empty() ? name : std::string(", ") + name;
  });
  if (missing.empty()) return true;
  if (error) *error = "the GL context's getProcAddress resolves no " + missing;
  return false;
}

bool checkGlError(const char* phase, std::string* error) {
  std::string codes;
  // glGetError returns one flag per call; a bounded loop also ends if the context is lost.
  for (int i = 0; i < 16; ++i) {
    const GLenum code = glGetError();
    if (code == GL_NO_ERROR) break;
    if (!codes.empty()) codes += ", ";
    codes += glErrorName(code);
  }
  if (codes.empty()) return true;
  if (error) *error = "GL error " + codes + " after " + phase;
  return false;
}

}  // namespace facet::runtime::gl
