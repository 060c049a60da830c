// Owning handles for GL object names.
//
// A handle deletes its name in whatever context is current when it dies, so the owner of a set of
// handles makes its context current before destroying them (GlBackend's destructor does).
#pragma once

#include <utility>

#include "gl_api.h"

namespace facet::runtime::gl {

enum class Kind { Buffer, VertexArray, Texture, Renderbuffer, Framebuffer, Shader, Program, Query, Sampler };

template <Kind K>
class Object {
 public:
  Object() = default;
  // Takes ownership of a name made elsewhere (glCreateShader, glCreateProgram).
  explicit Object(GLuint id) : id_(id) {}
  ~Object() { reset(); }

  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  Object(Object&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  Object& operator=(Object&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }

  // A fresh name from glGen* (for the kinds that have one).
  static Object generate() {
    GLuint id = 0;
    if constexpr (K == Kind::Buffer) glGenBuffers(1, &id);
    if constexpr (K == Kind::VertexArray) glGenVertexArrays(1, &id);
    if constexpr (K == Kind::Texture) glGenTextures(1, &id);
    if constexpr (K == Kind::Renderbuffer) glGenRenderbuffers(1, &id);
    if constexpr (K == Kind::Framebuffer) glGenFramebuffers(1, &id);
    if constexpr (K == Kind::Query) glGenQueries(1, &id);
    if constexpr (K == Kind::Sampler) glGenSamplers(1, &id);
    static_assert(K != Kind::Shader && K != Kind::Program, "use the GLuint constructor");
    return Object(id);
  }

  GLuint id() const { return id_; }

  void reset() {
    if (id_ == 0) return;
    if constexpr (K == Kind::Buffer) glDeleteBuffers(1, &id_);
    if constexpr (K == Kind::VertexArray) glDeleteVertexArrays(1, &id_);
    if constexpr (K == Kind::Texture) glDeleteTextures(1, &id_);
    if constexpr (K == Kind::Renderbuffer) glDeleteRenderbuffers(1, &id_);
    if constexpr (K == Kind::Framebuffer) glDeleteFramebuffers(1, &id_);
    if constexpr (K == Kind::Shader) glDeleteShader(id_);
    if constexpr (K == Kind::Program) glDeleteProgram(id_);
    if constexpr (K == Kind::Query) glDeleteQueries(1, &id_);
    if constexpr (K == Kind::Sampler) glDeleteSamplers(1, &id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

using Buffer = Object<Kind::Buffer>;
using VertexArray = Object<Kind::VertexArray>;
using Texture = Object<Kind::Texture>;
using Renderbuffer = Object<Kind::Renderbuffer>;
using Framebuffer = Object<Kind::Framebuffer>;
using Shader = Object<Kind::Shader>;
using Program = Object<Kind::Program>;
using Query = Object<Kind::Query>;
using Sampler = Object<Kind::Sampler>;

}  // namespace facet::runtime::gl
