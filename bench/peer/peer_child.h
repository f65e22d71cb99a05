// Runs the llvmpipe runner (bench/llvmpipe/) as a child process: llvmpipe reads LP_NUM_THREADS
// once at start-up, so every thread count needs its own process.
#pragma once
#include <filesystem>
#include <string>

#include "frame_times.h"
#include "util/error.h"

namespace ontile::peer {

struct LlvmpipeRequest {
  std::filesystem::path runner, scene;
  int width_px = 1920, height_px = 1080, frames = 5, threads = 1;
  std::string pipeline = "lambert";  // or "cartoon"
  std::filesystem::path color_png;
  std::filesystem::path primitive_ids_exr;  // lambert only
  std::filesystem::path edges_png;          // cartoon only: the Sobel edge mask
};

struct LlvmpipeRun {
  FrameTimes times;
  std::string renderer;  // the runner's "renderer:" line
};

// The runner's exit status when EGL, the surfaceless platform or llvmpipe is missing.
constexpr int kLlvmpipeUnavailableExit = 77;
// Thrown when the runner exits with kLlvmpipeUnavailableExit: the machine lacks the runtime.
struct LlvmpipeUnavailable : Error {
  using Error::Error;
};

// Throws LlvmpipeUnavailable when the runtime is missing, otherwise ontile::Error with the
// child's last output line when it fails or prints no timings.
LlvmpipeRun run_llvmpipe(const LlvmpipeRequest& request);

}  // namespace ontile::peer
