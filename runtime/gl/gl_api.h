// The one place the GL backend includes GL. The prototypes resolve against libOSMesa, which
// exports every gl* entry point and dispatches to whichever OSMesa context is current, so no
// function-pointer loader is needed.
#pragma once

#if defined(__gl_h_) && !defined(GL_GLEXT_PROTOTYPES)
#error "GL/gl.h was included before gl_api.h: GL/glext.h would lack the function prototypes"
#endif
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

namespace facet::runtime::gl {

// Drains glGetError. Returns true when no error was pending; otherwise returns false and sets
// *error to "GL error GL_INVALID_OPERATION after <phase>" (all pending codes listed).
bool checkGlError(const char* phase, std::string* error);

}  // namespace facet::runtime::gl
