// Runs the llvmpipe runner (bench/llvmpipe/) as a child process: llvmpipe reads LP_NUM_THREADS
// once at start-up, so every thread count needs its own process.
#pragma once
#include <filesystem>
#include <string>

#include "frame_times.h"

namespace ontile::peer {

struct LlvmpipeRequest {
  std::filesystem::path runner, scene;
  int width_px = 1920, height_px = 1080, frames = 5, threads = 1;
  std::filesystem::path color_png, primitive_ids_exr;  // written by the child
};

struct LlvmpipeRun {
  FrameTimes times;
  std::string renderer;  // the runner's "renderer:" line
};

// Throws ontile::Error with the child's last output line when it fails or prints no timings.
LlvmpipeRun run_llvmpipe(const LlvmpipeRequest& request);

}  // namespace ontile::peer
