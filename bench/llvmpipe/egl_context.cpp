// EGL surfaceless set-up for the llvmpipe runner (see egl_context.h).
#include "egl_context.h"

#include <cstdlib>
#include <cstring>

#include <EGL/eglext.h>
#include <GLES3/gl32.h>

#include "util/error.h"

namespace ontile::peer {
namespace {

std::string egl_error(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  return std::string("EGL: ") + what + " failed (error " + code + ")";
}

}  // namespace

void force_llvmpipe_environment() {
  setenv("EGL_PLATFORM", "surfaceless", 0);
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  setenv("GALLIUM_DRIVER", "llvmpipe", 0);
}

EglContext::EglContext() {
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client_extensions || !std::strstr(client_extensions, "EGL_MESA_platform_surfaceless")) {
    throw Error("EGL: EGL_MESA_platform_surfaceless is not available (install libegl-mesa0)");
  }
  display_ = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
    throw Error(egl_error("eglInitialize on the surfaceless platform"));
  }
  if (!eglBindAPI(EGL_OPENGL_ES_API)) throw Error(egl_error("eglBindAPI(OpenGL ES)"));
  // No config: the context only ever draws into framebuffer objects (EGL_KHR_no_config_context).
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2, EGL_NONE};
  context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context_ == EGL_NO_CONTEXT) throw Error(egl_error("creating a GLES 3.2 context"));
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    throw Error(egl_error("eglMakeCurrent without surface"));
  }
  if (renderer().find("llvmpipe") == std::string::npos) {
    throw Error("EGL: the GLES driver is '" + renderer() + "', not llvmpipe (is GALLIUM_DRIVER overridden?)");
  }
}

EglContext::~EglContext() {
  if (display_ == EGL_NO_DISPLAY) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

std::string EglContext::renderer() const {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name ? name : "";
}

bool EglContext::has_extension(const std::string& name) const {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (e && name == e) return true;
  }
  return false;
}

}  // namespace ontile::peer
