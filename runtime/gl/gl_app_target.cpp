#include "gl_app_target.h"

#include "gl_targets.h"

namespace facet::runtime::gl {
namespace {

GLint attachmentParameter(GLenum attachment, GLenum parameter) {
  GLint value = 0;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, attachment, parameter, &value);
  return value;
}

std::string describe(const GlAppTarget& target) {
  return target.framebuffer == 0 ? std::string("the default framebuffer")
                                 : "framebuffer " + std::to_string(target.framebuffer);
}

}  // namespace

bool inspectAppTarget(const GlAppTarget& target, uint32_t frameWidth, uint32_t frameHeight, bool es,
                      AppAttachment* attachment, std::string* error) {
  if (target.width != frameWidth || target.height != frameHeight) {
    *error = "the app's target is " + std::to_string(target.width) + "x" + std::to_string(target.height) +
             " but the frame is " + std::to_string(frameWidth) + "x" + std::to_string(frameHeight);
    return false;
  }
  // Binding a name that is no framebuffer object of this context raises GL_INVALID_OPERATION in
  // the app's debug output: asked first. (A name generated but never bound is not one yet either,
  // and would be incomplete anyway: it has no attachments.)
  if (target.framebuffer != 0 && glIsFramebuffer(target.framebuffer) == GL_FALSE) {
    *error = describe(target) + " is not a framebuffer object of the current context";
    return false;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    *error = describe(target) + " is not complete: " + framebufferStatusName(status);
    return false;
  }

  GLint drawBuffer = GL_NONE;
  glGetIntegerv(GL_DRAW_BUFFER0, &drawBuffer);
  if (drawBuffer == GL_NONE) {
    *error = describe(target) + " has draw buffer 0 set to GL_NONE: the post pass would write nothing";
    return false;
  }
  // Desktop GL names the default framebuffer's colour buffers *_LEFT in attachment queries.
  GLenum queried = static_cast<GLenum>(drawBuffer);
  if (!es && target.framebuffer == 0) queried = queried == GL_FRONT ? GL_FRONT_LEFT : GL_BACK_LEFT;

  const GLint type = attachmentParameter(queried, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
  if (type == GL_NONE) {
    *error = describe(target) + " has no image at its draw buffer 0";
    return false;
  }
  // The post shader writes sRGB-encoded bytes: an sRGB attachment would encode them again, a
  // float or integer one would not hold what render() returns.
  if (attachmentParameter(queried, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE) != GL_UNSIGNED_NORMALIZED) {
    *error = describe(target) + "'s draw buffer 0 is not unsigned-normalised (GL_RGBA8, GL_RGB8)";
    return false;
  }
  if (attachmentParameter(queried, GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING) != GL_LINEAR) {
    *error = describe(target) +
             "'s draw buffer 0 is sRGB-encoded: the post pass writes encoded bytes, which it would encode twice "
             "(use GL_RGBA8, and sample it as sRGB through a view or in the shader)";
    return false;
  }

  AppAttachment found;
  found.type = static_cast<GLenum>(type);
  if (found.type == GL_TEXTURE || found.type == GL_RENDERBUFFER) {
    found.name = static_cast<GLuint>(attachmentParameter(queried, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME));
  }
  if (found.type == GL_TEXTURE) {
    found.level = attachmentParameter(queried, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL);
    const GLint face = attachmentParameter(queried, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE);
    if (face != 0) found.textureTarget = static_cast<GLenum>(face);
    if (attachmentParameter(queried, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER) != 0) {
      *error = describe(target) +
               "'s draw buffer 0 is a layer of an array or 3D texture, which the backend "
               "does not attach (a 2D texture, a cube face or a renderbuffer)";
      return false;
    }
  }
  *attachment = found;
  return true;
}

bool attachAppImage(const AppAttachment& attachment, std::string* error) {
  if (attachment.type == GL_TEXTURE) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, attachment.textureTarget, attachment.name,
                           attachment.level);
  } else {
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, attachment.name);
  }
  if (!checkGlError("attaching the app's image", error)) {
    detachAppImage(attachment);
    return false;
  }
  if (checkComplete("the merged framebuffer (HDR + depth + the app's image)", error)) return true;
  detachAppImage(attachment);
  return false;
}

void detachAppImage(const AppAttachment& attachment) {
  if (attachment.type == GL_TEXTURE) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);
  } else {
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, 0);
  }
}

}  // namespace facet::runtime::gl
