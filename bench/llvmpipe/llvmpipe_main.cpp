// ontile_llvmpipe: renders a glTF scene with Mesa's llvmpipe (EGL surfaceless, GLES 3.2) the
// way ontile's lambert or cartoon pipeline renders it, times N frames after a warm-up and
// writes the colour and the primitive-id AOV (lambert) or the Sobel edge mask (cartoon); the
// peer benchmark (bench/peer/) runs it once per LP_NUM_THREADS value.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <EGL/egl.h>
#include <GLES3/gl32.h>
#include <GLES2/gl2ext.h>

#include "../peer/frame_times.h"
#include "egl_context.h"
#include "gl_cartoon.h"
#include "gl_state.h"
#include "gl_scene.h"
#include "io/image_io.h"
#include "pipelines/lit/lit_shader.h"
#include "pipelines/kit/render_frame.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile::peer {
namespace {

struct Options {
  std::string scene, size = "1920x1080", pipeline = "lambert", color, primitive_ids, edges;
  int camera = -1, frames = 5;
};

// Exit status when EGL, the surfaceless platform or llvmpipe cannot be opened: the runtime is
// missing rather than the frame wrong, so callers (the peer test) can skip.
constexpr int kRuntimeUnavailableExit = 77;
struct RuntimeUnavailable : Error {
  using Error::Error;
};

void parse_size(const std::string& text, int& w, int& h) {
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w <= 0 || h <= 0 ||
      w > 16384 || h > 16384) {
    throw Error("--size '" + text + "': expected WIDTHxHEIGHT, 1..16384 each, e.g. 1920x1080");
  }
}

// A colour (SRGB8_ALPHA8, as ontile's RGBA8_SRGB target), a primitive-id (R32UI) and a 32-bit
// float depth renderbuffer, in two framebuffers sharing the depth.
struct Framebuffers {
  GLuint color_rb = 0, ids_rb = 0, depth_rb = 0, color_fbo = 0, ids_fbo = 0;

  Framebuffers(int w, int h) {
    auto storage = [&](GLuint& rb, GLenum format) {
      glGenRenderbuffers(1, &rb);
      glBindRenderbuffer(GL_RENDERBUFFER, rb);
      glRenderbufferStorage(GL_RENDERBUFFER, format, w, h);
    };
    storage(color_rb, GL_SRGB8_ALPHA8);
    storage(ids_rb, GL_R32UI);
    storage(depth_rb, GL_DEPTH_COMPONENT32F);
    auto framebuffer = [&](GLuint& fbo, GLuint color) {
      glGenFramebuffers(1, &fbo);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw Error("llvmpipe runner: incomplete framebuffer");
      }
    };
    framebuffer(color_fbo, color_rb);
    framebuffer(ids_fbo, ids_rb);
  }
  ~Framebuffers() {
    const GLuint fbos[] = {color_fbo, ids_fbo}, rbs[] = {color_rb, ids_rb, depth_rb};
    glDeleteFramebuffers(2, fbos);
    glDeleteRenderbuffers(3, rbs);
  }
};

void run(const Options& o) {
  int w = 0, h = 0;
  parse_size(o.size, w, h);
  const bool cartoon = o.pipeline == "cartoon";
  if (!cartoon && o.pipeline != "lambert") throw Error("--pipeline '" + o.pipeline + "': expected lambert or cartoon");
  if (cartoon && !o.primitive_ids.empty()) throw Error("--primitive-ids: only with --pipeline lambert");
  if (!cartoon && !o.edges.empty()) throw Error("--edges: only with --pipeline cartoon");
  auto require_extension = [](const std::string& path, const char* ext) {
    if (!path.empty() && std::filesystem::path(path).extension() != ext) {
      throw Error(path + ": expected a " + ext + " file");
    }
  };
  require_extension(o.color, ".png");
  require_extension(o.primitive_ids, ".exr");
  require_extension(o.edges, ".png");
  const Scene scene = load_gltf(o.scene);
  // The camera `ontile render` picks and the pipelines' matrices (Vulkan clip space: z in
  // [0, w], +Y up in NDC, which is also GL's NDC orientation).
  const CameraMatrices camera = camera_matrices(select_camera(scene, o.camera), double(w) / h);
  const DirectionalLighting lighting = main_directional_light(scene);

  std::unique_ptr<EglContext> egl;
  try {
    egl = std::make_unique<EglContext>();
  } catch (const Error& e) {
    throw RuntimeUnavailable(e.what());
  }
  // Y flipped (exact in float) so that GL's row 0, the first row in memory, is ontile's top
  // row. llvmpipe breaks edge ties with the top-left rule in memory order (row 0 first), so
  // this gives ontile's D3D top-left rule in image space; unflipped, pixel centres exactly on
  // a horizontal edge go to the triangle above it instead of the one below. The flip mirrors
  // the winding, hence glFrontFace(GL_CW) for glTF's counter-clockwise front faces.
  glm::dmat4 to_gl(1.0);
  to_gl[1][1] = -1.0;
  const bool clip_control = egl->has_extension("GL_EXT_clip_control");
  if (clip_control) {
    // Depth in [0, 1] straight from z / w, as ontile computes it: same precision, same ties.
    const auto clip_control_ext =
        reinterpret_cast<PFNGLCLIPCONTROLEXTPROC>(eglGetProcAddress("glClipControlEXT"));
    clip_control_ext(GL_LOWER_LEFT_EXT, GL_ZERO_TO_ONE_EXT);
  } else {
    to_gl[2][2] = 2.0;  // z' = 2 z - w: GL's [-w, w] clip range
    to_gl[3][2] = -1.0;
  }
  const glm::dmat4 view_projection = to_gl * camera.view_projection;
  glFrontFace(GL_CW);
  GlScene gl_scene(scene);
  glViewport(0, 0, w, h);
  glDisable(GL_SCISSOR_TEST);

  // One frame of the chosen pipeline into its targets, returning the scene draws recorded.
  std::function<size_t()> frame;
  std::unique_ptr<GlPrograms> programs;
  std::unique_ptr<Framebuffers> fb;
  std::unique_ptr<GlCartoonFrame> cartoon_frame;
  if (cartoon) {
    cartoon_frame = std::make_unique<GlCartoonFrame>(scene, gl_scene, camera, view_projection, w, h);
    frame = [&] { return cartoon_frame->render(); };
  } else {
    programs = std::make_unique<GlPrograms>();
    fb = std::make_unique<Framebuffers>(w, h);
    frame = [&] {
      glBindFramebuffer(GL_FRAMEBUFFER, fb->color_fbo);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glDepthMask(GL_TRUE);
      const glm::vec4 bg = lit::kBackgroundColor;  // linear; GL encodes clears of sRGB targets
      glClearColor(bg.x, bg.y, bg.z, bg.w);
      glClearDepthf(1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      return gl_scene.draw_lambert(view_projection, camera, lighting, *programs);
    };
  }
  size_t draws = 0;
  // The warm-up compiles llvmpipe's shader variants (JIT) and touches every buffer once.
  draws = frame();
  glFinish();
  check_gl("the warm-up frame");
  std::vector<double> ms;
  const double cpu_start = process_cpu_ms();
  for (int i = 0; i < o.frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    draws = frame();
    glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  check_gl("the timed frames");
  const FrameTimes times = summarize_frames(ms, process_cpu_ms() - cpu_start);
  const char* lp_threads = std::getenv("LP_NUM_THREADS");
  std::printf("renderer: %s, LP_NUM_THREADS=%s\n", egl->renderer().c_str(), lp_threads ? lp_threads : "(unset)");
  std::printf("scene: %s, %s, %dx%d, %llu triangles, %zu draws, depth %s\n", o.scene.c_str(), o.pipeline.c_str(), w, h,
              static_cast<unsigned long long>(scene.drawn_triangle_count()), draws,
              clip_control ? "[0,1] (GL_EXT_clip_control)" : "[-1,1] (remapped projection)");
  std::printf("frames: %d after 1 warm-up\nmedian_ms: %.3f\nmin_ms: %.3f\ncpu_ms_per_frame: %.3f\ncores_busy: %.2f\n",
              o.frames, times.median_ms, times.min_ms, times.cpu_ms_per_frame, times.cores_busy);

  if (!o.color.empty()) {
    std::vector<uint8_t> rgba(static_cast<size_t>(w) * h * 4);
    if (cartoon) {
      rgba = cartoon_frame->read_color();
    } else {
      glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
      check_gl("reading the colour");
    }
    write_png_rgba8(o.color, w, h, rgba);  // rows already top first (see the Y flip)
    std::printf("wrote %s\n", o.color.c_str());
  }
  if (!o.edges.empty()) {
    const std::vector<uint8_t> mask = cartoon_frame->edge_mask();
    std::vector<uint8_t> rgba(mask.size() * 4);
    for (size_t i = 0; i < mask.size(); ++i) rgba[i * 4] = rgba[i * 4 + 1] = rgba[i * 4 + 2] = mask[i], rgba[i * 4 + 3] = 255;
    write_png_rgba8(o.edges, w, h, rgba);
    std::printf("wrote %s\n", o.edges.c_str());
  }
  if (!o.primitive_ids.empty()) {
    glBindFramebuffer(GL_FRAMEBUFFER, fb->ids_fbo);
    const GLuint no_id[4] = {~0u, 0, 0, 0};
    const GLfloat far_depth = 1.0f;
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClearBufferuiv(GL_COLOR, 0, no_id);
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    gl_scene.draw_primitive_ids(view_projection, camera, *programs);
    std::vector<GLuint> ids(static_cast<size_t>(w) * h * 4);
    glReadPixels(0, 0, w, h, GL_RGBA_INTEGER, GL_UNSIGNED_INT, ids.data());
    check_gl("the primitive-id pass");
    // As ontile's AOV: the id as float (exact below 2^24), -1 where no opaque surface is.
    std::vector<float> channel(static_cast<size_t>(w) * h);
    for (size_t i = 0; i < channel.size(); ++i) channel[i] = ids[i * 4] == ~0u ? -1.0f : static_cast<float>(ids[i * 4]);
    write_exr_channels(o.primitive_ids, w, h, {"primid"}, channel);
    std::printf("wrote %s\n", o.primitive_ids.c_str());
  }
}

}  // namespace
}  // namespace ontile::peer

int main(int argc, char** argv) {
  ontile::peer::force_llvmpipe_environment();
  CLI::App app{"ontile_llvmpipe: ontile's lambert or cartoon frame on Mesa llvmpipe (set LP_NUM_THREADS for its "
               "threads); exits with 77 when EGL or llvmpipe is unavailable"};
  ontile::peer::Options o;
  app.add_option("--scene", o.scene, "glTF scene (.gltf or .glb)")->required()->check(CLI::ExistingFile);
  app.add_option("--camera", o.camera, "Camera index (default: as `ontile render`)")->check(CLI::Range(0, 1 << 20));
  app.add_option("--size", o.size, "Image size WIDTHxHEIGHT (default 1920x1080)");
  app.add_option("--frames", o.frames, "Timed frames after one warm-up (default 5)")->check(CLI::Range(1, 100000));
  app.add_option("--pipeline", o.pipeline, "lambert (default) or cartoon");
  app.add_option("--color", o.color, "Write the last frame's colour here (.png)");
  app.add_option("--edges", o.edges, "cartoon: write the Sobel edge mask here (.png, 255 = edge)");
  app.add_option("--primitive-ids", o.primitive_ids, "lambert: write the primitive-id AOV here (.exr, channel primid)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  try {
    ontile::peer::run(o);
  } catch (const ontile::peer::RuntimeUnavailable& e) {
    std::fprintf(stderr, "unavailable: %s\n", e.what());
    return ontile::peer::kRuntimeUnavailableExit;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
