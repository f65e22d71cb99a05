// A GLES 3.2 context on Mesa's llvmpipe through EGL surfaceless (EGL_MESA_platform_surfaceless):
// no window system, rendering goes to framebuffer objects only.
#pragma once
#include <string>

#include <EGL/egl.h>

namespace ontile::peer {

class EglContext {
 public:
  // Creates the display and context and makes it current on this thread. Throws ontile::Error
  // when EGL, the surfaceless platform or a GLES 3.2 context is unavailable, or when the driver
  // is not llvmpipe (a hardware driver would make the comparison meaningless).
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  bool has_extension(const std::string& name) const;

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

// Sets the variables that force Mesa's software path and the surfaceless platform, unless the
// caller's environment already sets them. Must run before the first EGL call.
void force_llvmpipe_environment();

}  // namespace ontile::peer
