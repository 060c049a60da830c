// The app's framebuffer as the post pass's target (GlAppTarget, facet/runtime/gl_backend.h): checked
// before a frame draws anything, and on the merged path its draw buffer 0's image lent to the
// backend's framebuffer-fetch framebuffer as colour 1 for the length of one frame.
#pragma once

#include <cstdint>
#include <string>

#include "facet/runtime/gl_backend.h"
#include "gl_objects.h"

namespace facet::runtime::gl {

// The image behind the app framebuffer's draw buffer 0.
struct AppAttachment {
  GLenum type = GL_NONE;  // GL_TEXTURE, GL_RENDERBUFFER, or GL_FRAMEBUFFER_DEFAULT (framebuffer 0)
  GLuint name = 0;
  GLint level = 0;
  GLenum textureTarget = GL_TEXTURE_2D;  // or the GL_TEXTURE_CUBE_MAP_* face attached
};

// Checks `target` against the frame's size and the rules of GlAppTarget, leaving it bound to
// GL_FRAMEBUFFER, and describes its draw buffer 0. Returns false with *error naming the reason for
// any unusable target, without raising a GL error (the app's debug output stays clean). `es`:
// the context is OpenGL ES (desktop GL names the default framebuffer's buffers differently).
bool inspectAppTarget(const GlAppTarget& target, uint32_t frameWidth, uint32_t frameHeight, bool es,
                      AppAttachment* attachment, std::string* error);

// Attaches the app's image as colour 1 of the framebuffer bound to GL_FRAMEBUFFER and checks
// that framebuffer is complete with it (same sample count; the app's image must be the frame's
// size, which ES 3.0 cannot query for a texture). On failure the image is detached again.
bool attachAppImage(const AppAttachment& attachment, std::string* error);
// Detaches colour 1 of the framebuffer bound to GL_FRAMEBUFFER, so the backend holds no reference
// to the app's image between frames (an image the app deletes is freed, a reused name is not ours).
void detachAppImage(const AppAttachment& attachment);

}  // namespace facet::runtime::gl
