// The OpenGL 3.3+ core functions the renderer uses, loaded through the context's get-proc-address
// (OSMesaGetProcAddress here, eglGetProcAddress on a GPU), so the same rendering code runs on any
// context. libOSMesa does not export every core function (glClipControl, for one), hence the
// loader rather than link-time symbols.
//
// Input: a function that returns the address of a GL entry point by name (nullptr when absent).
// Output: a table of function pointers named as GL names them without the "gl" prefix
// (gl.CreateShader(...)). A missing function throws std::runtime_error naming it.
#pragma once

#include <GL/glcorearb.h>

#include <functional>

namespace fedsim::gl {

using GlProcLoader = std::function<void*(const char* name)>;

// X(type of the pointer, name without "gl")
#define FEDSIM_GL_FUNCTIONS(X)                                         \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                             \
  X(PFNGLATTACHSHADERPROC, AttachShader)                               \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                   \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                         \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                       \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                                 \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                         \
  X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                     \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                         \
  X(PFNGLBUFFERDATAPROC, BufferData)                                   \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)           \
  X(PFNGLCLEARPROC, Clear)                                             \
  X(PFNGLCLEARCOLORPROC, ClearColor)                                   \
  X(PFNGLCLEARDEPTHPROC, ClearDepth)                                   \
  X(PFNGLCLIPCONTROLPROC, ClipControl)                                 \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                             \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                             \
  X(PFNGLCREATESHADERPROC, CreateShader)                               \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                             \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                   \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                             \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                 \
  X(PFNGLDELETESHADERPROC, DeleteShader)                               \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                           \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                   \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                                     \
  X(PFNGLDEPTHMASKPROC, DepthMask)                                     \
  X(PFNGLDISABLEPROC, Disable)                                         \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                                   \
  X(PFNGLENABLEPROC, Enable)                                           \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)         \
  X(PFNGLFINISHPROC, Finish)                                           \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)         \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                   \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                         \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                       \
  X(PFNGLGENTEXTURESPROC, GenTextures)                                 \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                         \
  X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)                           \
  X(PFNGLGETERRORPROC, GetError)                                       \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                                 \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                     \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                               \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                       \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                                 \
  X(PFNGLGETSTRINGPROC, GetString)                                     \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                   \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                                 \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                                 \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                                   \
  X(PFNGLREADPIXELSPROC, ReadPixels)                                   \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                 \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample) \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                               \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                   \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                             \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                                     \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                     \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                                     \
  X(PFNGLUNIFORM3FPROC, Uniform3f)                                     \
  X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                       \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                       \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                   \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                 \
  X(PFNGLVIEWPORTPROC, Viewport)

struct GlApi {
  explicit GlApi(const GlProcLoader& loader);

#define FEDSIM_GL_DECLARE(type, name) type name = nullptr;
  FEDSIM_GL_FUNCTIONS(FEDSIM_GL_DECLARE)
#undef FEDSIM_GL_DECLARE

  /// Throws std::runtime_error("<what>: OpenGL error 0x...") if the GL error flag is set.
  void check(const char* what) const;
};

}  // namespace fedsim::gl
