// Consumer of the installed ontile package: loads the bundled demo scene, renders it with the
// cartoon pipeline through the public C++ API, writes the image and prints the frame's external
// memory traffic. Usage: render_demo OUT.png
#include <cstdio>
#include <exception>

#include "io/image_io.h"
#include "pipelines/kit/render_frame.h"
#include "scene/gltf_loader.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: render_demo OUT.png\n");
    return 2;
  }
  try {
    const ontile::Scene scene = ontile::load_gltf(ONTILE_DEMO_SCENE);
    ontile::RenderSettings settings;
    settings.pipeline = "cartoon";  // registered by the pipelines library, linked whole
    settings.width_px = 320;
    settings.height_px = 180;
    settings.context.threads = 2;
    const ontile::RenderedFrame frame = ontile::render_frame(scene, settings);
    const ontile::Surface& color = *frame.outputs.color;
    ontile::write_png_rgba8(argv[1], color.width(), color.height(), color.bytes());
    std::printf("passes: %zu\n", frame.outputs.report.passes.size());
    std::printf("bytes_read: %llu\n", static_cast<unsigned long long>(frame.outputs.report.bytes_read()));
    std::printf("bytes_written: %llu\n", static_cast<unsigned long long>(frame.outputs.report.bytes_written()));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
