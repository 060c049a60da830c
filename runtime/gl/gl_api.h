// The one place the GL backend includes GL: a table of the OpenGL ES 3.0 entry points it calls,
// resolved per context through that context's getProcAddress (eglGetProcAddress, an app's
// SDL_GL_GetProcAddress, OSMesaGetProcAddress in tests), so facet_runtime_gl links no GL library.
// The same names exist in desktop GL 4.3 core with the same signatures (ES 3.0 is a subset), which
// is why the types come from GL/glcorearb.h: it declares a PFN type for every function and no
// prototypes (GL_GLEXT_PROTOTYPES unset), so a gl* call that is not in the table fails to compile.
//
// Call sites keep writing glGenBuffers(...): each name is a macro reading the table of the context
// made current last on this thread (Context::makeCurrent), the way glad's loader does it. Adding a
// function: one line in FACET_GL_FUNCTIONS and one #define, both in the order of this list.
#pragma once

#if defined(__gl_h_) || defined(GL_GLEXT_PROTOTYPES)
#error "gl_api.h replaces GL/gl.h: include no other GL header (and no GL_GLEXT_PROTOTYPES) in backend code"
#endif
#include <GL/glcorearb.h>

#include <functional>
#include <string>

namespace facet::runtime::gl {

// X(type, name) for every required entry point.
#define FACET_GL_FUNCTIONS(X)                                                            \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                                             \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                                               \
  X(PFNGLBEGINQUERYPROC, glBeginQuery)                                                   \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                                                   \
  X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                                           \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                                         \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                                       \
  X(PFNGLBINDSAMPLERPROC, glBindSampler)                                                 \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                                                 \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                                         \
  X(PFNGLBLENDCOLORPROC, glBlendColor)                                                   \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                                                     \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                                         \
  X(PFNGLBUFFERDATAPROC, glBufferData)                                                   \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                                             \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)                           \
  X(PFNGLCLEARBUFFERFVPROC, glClearBufferfv)                                             \
  X(PFNGLCOLORMASKPROC, glColorMask)                                                     \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                                             \
  X(PFNGLCOMPRESSEDTEXIMAGE2DPROC, glCompressedTexImage2D)                               \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                             \
  X(PFNGLCREATESHADERPROC, glCreateShader)                                               \
  X(PFNGLCULLFACEPROC, glCullFace)                                                       \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                             \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                                   \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                             \
  X(PFNGLDELETEQUERIESPROC, glDeleteQueries)                                             \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)                                 \
  X(PFNGLDELETESAMPLERSPROC, glDeleteSamplers)                                           \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                                               \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                                           \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                                   \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                                     \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                                                     \
  X(PFNGLDETACHSHADERPROC, glDetachShader)                                               \
  X(PFNGLDISABLEPROC, glDisable)                                                         \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                                   \
  X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                                                 \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                                               \
  X(PFNGLDRAWELEMENTSINSTANCEDPROC, glDrawElementsInstanced)                             \
  X(PFNGLENABLEPROC, glEnable)                                                           \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)                         \
  X(PFNGLENDQUERYPROC, glEndQuery)                                                       \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)                         \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)                               \
  X(PFNGLFRONTFACEPROC, glFrontFace)                                                     \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                                                   \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                                         \
  X(PFNGLGENQUERIESPROC, glGenQueries)                                                   \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                                       \
  X(PFNGLGENSAMPLERSPROC, glGenSamplers)                                                 \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                                                 \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                                         \
  X(PFNGLGETACTIVEATTRIBPROC, glGetActiveAttrib)                                         \
  X(PFNGLGETACTIVEUNIFORMPROC, glGetActiveUniform)                                       \
  X(PFNGLGETACTIVEUNIFORMBLOCKNAMEPROC, glGetActiveUniformBlockName)                     \
  X(PFNGLGETACTIVEUNIFORMBLOCKIVPROC, glGetActiveUniformBlockiv)                         \
  X(PFNGLGETACTIVEUNIFORMSIVPROC, glGetActiveUniformsiv)                                 \
  X(PFNGLGETATTRIBLOCATIONPROC, glGetAttribLocation)                                     \
  X(PFNGLGETERRORPROC, glGetError)                                                       \
  X(PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVPROC, glGetFramebufferAttachmentParameteriv) \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                                 \
  X(PFNGLGETINTERNALFORMATIVPROC, glGetInternalformativ)                                 \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                                     \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                               \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                                       \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                                 \
  X(PFNGLGETSTRINGPROC, glGetString)                                                     \
  X(PFNGLGETSTRINGIPROC, glGetStringi)                                                   \
  X(PFNGLGETUNIFORMBLOCKINDEXPROC, glGetUniformBlockIndex)                               \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                                   \
  X(PFNGLINVALIDATEFRAMEBUFFERPROC, glInvalidateFramebuffer)                             \
  X(PFNGLISENABLEDPROC, glIsEnabled)                                                     \
  X(PFNGLISFRAMEBUFFERPROC, glIsFramebuffer)                                             \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                                 \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                                 \
  X(PFNGLPOLYGONOFFSETPROC, glPolygonOffset)                                             \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                                                   \
  X(PFNGLREADPIXELSPROC, glReadPixels)                                                   \
  X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)                                 \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, glRenderbufferStorageMultisample)           \
  X(PFNGLSAMPLERPARAMETERIPROC, glSamplerParameteri)                                     \
  X(PFNGLSCISSORPROC, glScissor)                                                         \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                                               \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                                                   \
  X(PFNGLTEXIMAGE3DPROC, glTexImage3D)                                                   \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                                             \
  X(PFNGLTEXSTORAGE2DPROC, glTexStorage2D)                                               \
  X(PFNGLTEXSUBIMAGE3DPROC, glTexSubImage3D)                                             \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                                     \
  X(PFNGLUNIFORMBLOCKBINDINGPROC, glUniformBlockBinding)                                 \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                                   \
  X(PFNGLVERTEXATTRIBDIVISORPROC, glVertexAttribDivisor)                                 \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)                                 \
  X(PFNGLVIEWPORTPROC, glViewport)

struct Functions {
#define FACET_GL_MEMBER(type, name) type name = nullptr;
  FACET_GL_FUNCTIONS(FACET_GL_MEMBER)
#undef FACET_GL_MEMBER

  // Calls visit(member, "name") for each entry point. Defined here, above the macros, where the
  // names still mean the members.
  template <typename Visit>
  void forEach(Visit&& visit) {
#define FACET_GL_VISIT(type, name) visit(name, #name);
    FACET_GL_FUNCTIONS(FACET_GL_VISIT)
#undef FACET_GL_VISIT
  }

  // Resolves every entry point through getProcAddress. Returns false and sets *error naming the
  // ones that did not resolve.
  bool load(const std::function<void*(const char*)>& getProcAddress, std::string* error);

  // Every entry a no-op returning zero (glGetError: GL_NO_ERROR): what the names call while no
  // context of the backend's is current, so a backend destroyed on the wrong thread or with the
  // app's context not current deletes nothing in someone else's context and does not crash.
  static const Functions& noContext();
};

namespace detail {
// The table of the context made current last by this code on this thread; noContext() before
// any, and after a failed makeCurrent.
extern thread_local const Functions* current;
}  // namespace detail

// Drains glGetError. Returns true when no error was pending; otherwise returns false and sets
// *error to "GL error GL_INVALID_OPERATION after <phase>" (all pending codes listed).
bool checkGlError(const char* phase, std::string* error);

}  // namespace facet::runtime::gl

// After the table: inside it the names are the members'.
#define glActiveTexture (::facet::runtime::gl::detail::current->glActiveTexture)
#define glAttachShader (::facet::runtime::gl::detail::current->glAttachShader)
#define glBeginQuery (::facet::runtime::gl::detail::current->glBeginQuery)
#define glBindBuffer (::facet::runtime::gl::detail::current->glBindBuffer)
#define glBindBufferBase (::facet::runtime::gl::detail::current->glBindBufferBase)
#define glBindFramebuffer (::facet::runtime::gl::detail::current->glBindFramebuffer)
#define glBindRenderbuffer (::facet::runtime::gl::detail::current->glBindRenderbuffer)
#define glBindSampler (::facet::runtime::gl::detail::current->glBindSampler)
#define glBindTexture (::facet::runtime::gl::detail::current->glBindTexture)
#define glBindVertexArray (::facet::runtime::gl::detail::current->glBindVertexArray)
#define glBlendColor (::facet::runtime::gl::detail::current->glBlendColor)
#define glBlendFunc (::facet::runtime::gl::detail::current->glBlendFunc)
#define glBlitFramebuffer (::facet::runtime::gl::detail::current->glBlitFramebuffer)
#define glBufferData (::facet::runtime::gl::detail::current->glBufferData)
#define glBufferSubData (::facet::runtime::gl::detail::current->glBufferSubData)
#define glCheckFramebufferStatus (::facet::runtime::gl::detail::current->glCheckFramebufferStatus)
#define glClearBufferfv (::facet::runtime::gl::detail::current->glClearBufferfv)
#define glColorMask (::facet::runtime::gl::detail::current->glColorMask)
#define glCompileShader (::facet::runtime::gl::detail::current->glCompileShader)
#define glCompressedTexImage2D (::facet::runtime::gl::detail::current->glCompressedTexImage2D)
#define glCreateProgram (::facet::runtime::gl::detail::current->glCreateProgram)
#define glCreateShader (::facet::runtime::gl::detail::current->glCreateShader)
#define glCullFace (::facet::runtime::gl::detail::current->glCullFace)
#define glDeleteBuffers (::facet::runtime::gl::detail::current->glDeleteBuffers)
#define glDeleteFramebuffers (::facet::runtime::gl::detail::current->glDeleteFramebuffers)
#define glDeleteProgram (::facet::runtime::gl::detail::current->glDeleteProgram)
#define glDeleteQueries (::facet::runtime::gl::detail::current->glDeleteQueries)
#define glDeleteRenderbuffers (::facet::runtime::gl::detail::current->glDeleteRenderbuffers)
#define glDeleteSamplers (::facet::runtime::gl::detail::current->glDeleteSamplers)
#define glDeleteShader (::facet::runtime::gl::detail::current->glDeleteShader)
#define glDeleteTextures (::facet::runtime::gl::detail::current->glDeleteTextures)
#define glDeleteVertexArrays (::facet::runtime::gl::detail::current->glDeleteVertexArrays)
#define glDepthFunc (::facet::runtime::gl::detail::current->glDepthFunc)
#define glDepthMask (::facet::runtime::gl::detail::current->glDepthMask)
#define glDetachShader (::facet::runtime::gl::detail::current->glDetachShader)
#define glDisable (::facet::runtime::gl::detail::current->glDisable)
#define glDrawArrays (::facet::runtime::gl::detail::current->glDrawArrays)
#define glDrawBuffers (::facet::runtime::gl::detail::current->glDrawBuffers)
#define glDrawElements (::facet::runtime::gl::detail::current->glDrawElements)
#define glDrawElementsInstanced (::facet::runtime::gl::detail::current->glDrawElementsInstanced)
#define glEnable (::facet::runtime::gl::detail::current->glEnable)
#define glEnableVertexAttribArray (::facet::runtime::gl::detail::current->glEnableVertexAttribArray)
#define glEndQuery (::facet::runtime::gl::detail::current->glEndQuery)
#define glFramebufferRenderbuffer (::facet::runtime::gl::detail::current->glFramebufferRenderbuffer)
#define glFramebufferTexture2D (::facet::runtime::gl::detail::current->glFramebufferTexture2D)
#define glFrontFace (::facet::runtime::gl::detail::current->glFrontFace)
#define glGenBuffers (::facet::runtime::gl::detail::current->glGenBuffers)
#define glGenFramebuffers (::facet::runtime::gl::detail::current->glGenFramebuffers)
#define glGenQueries (::facet::runtime::gl::detail::current->glGenQueries)
#define glGenRenderbuffers (::facet::runtime::gl::detail::current->glGenRenderbuffers)
#define glGenSamplers (::facet::runtime::gl::detail::current->glGenSamplers)
#define glGenTextures (::facet::runtime::gl::detail::current->glGenTextures)
#define glGenVertexArrays (::facet::runtime::gl::detail::current->glGenVertexArrays)
#define glGetActiveAttrib (::facet::runtime::gl::detail::current->glGetActiveAttrib)
#define glGetActiveUniform (::facet::runtime::gl::detail::current->glGetActiveUniform)
#define glGetActiveUniformBlockName (::facet::runtime::gl::detail::current->glGetActiveUniformBlockName)
#define glGetActiveUniformBlockiv (::facet::runtime::gl::detail::current->glGetActiveUniformBlockiv)
#define glGetActiveUniformsiv (::facet::runtime::gl::detail::current->glGetActiveUniformsiv)
#define glGetAttribLocation (::facet::runtime::gl::detail::current->glGetAttribLocation)
#define glGetError (::facet::runtime::gl::detail::current->glGetError)
#define glGetFramebufferAttachmentParameteriv \
  (::facet::runtime::gl::detail::current->glGetFramebufferAttachmentParameteriv)
#define glGetIntegerv (::facet::runtime::gl::detail::current->glGetIntegerv)
#define glGetInternalformativ (::facet::runtime::gl::detail::current->glGetInternalformativ)
#define glGetProgramInfoLog (::facet::runtime::gl::detail::current->glGetProgramInfoLog)
#define glGetProgramiv (::facet::runtime::gl::detail::current->glGetProgramiv)
#define glGetShaderInfoLog (::facet::runtime::gl::detail::current->glGetShaderInfoLog)
#define glGetShaderiv (::facet::runtime::gl::detail::current->glGetShaderiv)
#define glGetString (::facet::runtime::gl::detail::current->glGetString)
#define glGetStringi (::facet::runtime::gl::detail::current->glGetStringi)
#define glGetUniformBlockIndex (::facet::runtime::gl::detail::current->glGetUniformBlockIndex)
#define glGetUniformLocation (::facet::runtime::gl::detail::current->glGetUniformLocation)
#define glInvalidateFramebuffer (::facet::runtime::gl::detail::current->glInvalidateFramebuffer)
#define glIsEnabled (::facet::runtime::gl::detail::current->glIsEnabled)
#define glIsFramebuffer (::facet::runtime::gl::detail::current->glIsFramebuffer)
#define glLinkProgram (::facet::runtime::gl::detail::current->glLinkProgram)
#define glPixelStorei (::facet::runtime::gl::detail::current->glPixelStorei)
#define glPolygonOffset (::facet::runtime::gl::detail::current->glPolygonOffset)
#define glReadBuffer (::facet::runtime::gl::detail::current->glReadBuffer)
#define glReadPixels (::facet::runtime::gl::detail::current->glReadPixels)
#define glRenderbufferStorage (::facet::runtime::gl::detail::current->glRenderbufferStorage)
#define glRenderbufferStorageMultisample (::facet::runtime::gl::detail::current->glRenderbufferStorageMultisample)
#define glSamplerParameteri (::facet::runtime::gl::detail::current->glSamplerParameteri)
#define glScissor (::facet::runtime::gl::detail::current->glScissor)
#define glShaderSource (::facet::runtime::gl::detail::current->glShaderSource)
#define glTexImage2D (::facet::runtime::gl::detail::current->glTexImage2D)
#define glTexImage3D (::facet::runtime::gl::detail::current->glTexImage3D)
#define glTexParameteri (::facet::runtime::gl::detail::current->glTexParameteri)
#define glTexStorage2D (::facet::runtime::gl::detail::current->glTexStorage2D)
#define glTexSubImage3D (::facet::runtime::gl::detail::current->glTexSubImage3D)
#define glUniform1i (::facet::runtime::gl::detail::current->glUniform1i)
#define glUniformBlockBinding (::facet::runtime::gl::detail::current->glUniformBlockBinding)
#define glUseProgram (::facet::runtime::gl::detail::current->glUseProgram)
#define glVertexAttribDivisor (::facet::runtime::gl::detail::current->glVertexAttribDivisor)
#define glVertexAttribPointer (::facet::runtime::gl::detail::current->glVertexAttribPointer)
#define glViewport (::facet::runtime::gl::detail::current->glViewport)
