// GL contexts of the backend's own, for tests, the viewer and eval (facet_runtime_gl_headless):
// a real OpenGL ES 3.x context through EGL on Mesa's surfaceless platform (what a phone gives), or
// an OpenGL core context on OSMesa (llvmpipe) that accepts "#version 300 es" shaders, where EGL is
// missing. An app never links this: it hands the backend its own context (facet/runtime/gl_backend.h).
#pragma once

#include <memory>
#include <string>

#include "facet/runtime/gl_backend.h"

namespace facet::runtime::gl {

// Creates the context `kind` asks for and makes it current. Returns nullptr and sets *error when it
// is unavailable; Auto tries EGL, then OSMesa.
std::unique_ptr<GlContext> createHeadlessContext(GlContextKind kind, std::string* error);

}  // namespace facet::runtime::gl
