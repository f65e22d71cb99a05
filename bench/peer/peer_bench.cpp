// ontile_peer_bench: ontile's lambert and cartoon frames against Mesa llvmpipe (bench/llvmpipe/)
// on the same scenes, camera, size and shading; a frame-time table per pipeline, scene and
// thread count, and how many pixels agree: the same triangle (lambert's primitive-id AOVs) or
// the same edge decision (cartoon's Sobel pass), and the same colour.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/image_io.h"
#include "cartoon_reference.h"
#include "peer_child.h"
#include "peer_compare.h"
#include "peer_report.h"
#include "aov/aov_pass.h"
#include "pipelines/kit/render_frame.h"
#include "scene/gen/scene_generator.h"
#include "scene/gltf_loader.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/heap_tuning.h"

namespace ontile::peer {
namespace {

namespace fs = std::filesystem;

struct Options {
  int frames = 5;
  std::string scenes = "atrium,atrium-2m,ToyCar,DamagedHelmet,demo", size = "1920x1080", threads = "1,2";
  std::string pipelines = "lambert,cartoon";
  std::string markdown, llvmpipe = ONTILE_LLVMPIPE_RUNNER, keep;
};

// A benchmark scene: generated (written to a temporary .glb the child can load) or a file of
// ../shared/assets.
struct PeerScene {
  std::string name;
  std::string generator;  // non-empty: generate_scene(generator, size)
  double size = 1.0;
  std::string shared_relative;
};

// demo: the cartoon design's own scene (cel, MatCap and ToonEnv materials, borders).
const std::vector<PeerScene> kScenes = {{"atrium", "atrium", 1.0, ""},
                                        {"atrium-2m", "atrium", 8.0, ""},
                                        {"ToyCar", "", 1.0, "ToyCar/ToyCar.gltf"},
                                        {"DamagedHelmet", "", 1.0, "DamagedHelmet/DamagedHelmet.glb"},
                                        {"demo", "demo", 1.0, ""}};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

std::vector<int> parse_threads(const std::string& text) {
  std::vector<int> out;
  for (const std::string& item : split(text)) {
    char* end = nullptr;
    const long t = std::strtol(item.c_str(), &end, 10);
    if (*end || t < 1 || t > 1024) throw Error("--threads '" + text + "': expected a list like 1,2 (1..1024)");
    out.push_back(static_cast<int>(t));
  }
  if (out.empty()) throw Error("--threads '" + text + "': no thread count");
  return out;
}

std::vector<PeerScene> select_scenes(const std::string& filter) {
  std::vector<PeerScene> out;
  for (const std::string& name : split(filter)) {
    bool found = false;
    for (const PeerScene& s : kScenes) {
      if (lower(s.name) == lower(name)) out.push_back(s), found = true;
    }
    if (!found) throw Error("--scenes '" + name + "': unknown scene (atrium, atrium-2m, ToyCar, DamagedHelmet, demo)");
  }
  return out;
}

std::vector<std::string> select_pipelines(const std::string& text) {
  std::vector<std::string> out;
  for (const std::string& name : split(text)) {
    if (name != "lambert" && name != "cartoon") throw Error("--pipelines '" + name + "': expected lambert or cartoon");
    out.push_back(name);
  }
  if (out.empty()) throw Error("--pipelines '" + text + "': no pipeline");
  return out;
}

FrameTimes time_ontile(const Scene& scene, const RenderSettings& settings, int frames, RenderedFrame& last) {
  last = render_frame(scene, settings);  // warm-up
  std::vector<double> ms;
  const double cpu_start = process_cpu_ms();
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    last = render_frame(scene, settings);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return summarize_frames(ms, process_cpu_ms() - cpu_start);
}

std::string first_line_of_command(const std::string& command) {
  std::string out;
  if (FILE* p = popen(command.c_str(), "r")) {
    char buf[512];
    if (std::fgets(buf, sizeof buf, p)) out = buf;
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out.empty() ? "unknown" : out;
}

void run(const Options& o) {
  RenderSettings settings;
  char x = 0, extra = 0;
  if (std::sscanf(o.size.c_str(), "%d%c%d%c", &settings.width_px, &x, &settings.height_px, &extra) != 3 ||
      x != 'x' || settings.width_px <= 0 || settings.height_px <= 0) {
    throw Error("--size '" + o.size + "': expected WIDTHxHEIGHT, e.g. 1920x1080");
  }
  const std::vector<int> threads = parse_threads(o.threads);
  const std::vector<PeerScene> scenes = select_scenes(o.scenes);
  const std::vector<std::string> pipelines = select_pipelines(o.pipelines);
  if (access(o.llvmpipe.c_str(), X_OK) != 0) throw Error(o.llvmpipe + ": the llvmpipe runner is not an executable");
  // Outputs of both renderers: kept in --keep, else in a temporary folder removed at the end.
  const fs::path work = o.keep.empty() ? fs::temp_directory_path() / ("ontile_peer_" + std::to_string(getpid()))
                                       : fs::path(o.keep);
  fs::create_directories(work);
  struct RemoveOnExit {  // also when a run throws
    fs::path folder;
    ~RemoveOnExit() {
      std::error_code ignored;
      if (!folder.empty()) fs::remove_all(folder, ignored);
    }
  } cleanup{o.keep.empty() ? work : fs::path()};
  keep_freed_memory_in_the_heap();
  // Other work on the machine slows both renderers; the Markdown records the load around the run.
  const std::string load_before = first_line_of_command("cut -d' ' -f1-3 /proc/loadavg");

  std::vector<PeerRow> rows;
  std::string renderer;
  for (const PeerScene& ps : scenes) {
    fs::path file;
    if (!ps.generator.empty()) {
      file = work / ("generated_" + ps.name + ".glb");
      SceneGenOptions gen;
      gen.size = ps.size;
      generate_scene(ps.generator, gen, file);
    } else {
      file = fs::path(ONTILE_SHARED_ASSETS) / ps.shared_relative;
      if (!fs::exists(file)) {
        std::printf("skipping %s: %s not found\n", ps.name.c_str(), file.string().c_str());
        continue;
      }
    }
    const Scene scene = load_gltf(file);
    for (const std::string& pipeline : pipelines) {
      const bool cartoon = pipeline == "cartoon";
      settings.pipeline = pipeline;
      // ontile's edge decisions do not depend on the thread count: computed once per scene.
      CartoonReference reference;
      for (int t : threads) {
        PeerRow row;
        row.pipeline = pipeline;
        row.scene = ps.name;
        row.triangles = scene.drawn_triangle_count();
        row.threads = t;
        settings.context.threads = t;
        RenderedFrame last;
        row.ontile = time_ontile(scene, settings, o.frames, last);
        const std::string stem = pipeline + "_" + ps.name + "_t" + std::to_string(t);
        LlvmpipeRequest request{o.llvmpipe, file, settings.width_px, settings.height_px, o.frames, t, pipeline,
                                work / (stem + "_llvmpipe.png"), {}, {}};
        if (cartoon) {
          request.edges_png = work / (stem + "_llvmpipe_edges.png");
        } else {
          request.primitive_ids_exr = work / (stem + "_llvmpipe_ids.exr");
        }
        const LlvmpipeRun child = run_llvmpipe(request);
        renderer = child.renderer;
        row.llvmpipe = child.times;
        row.color = compare_colors(*last.outputs.color, request.color_png);
        if (cartoon) {
          if (reference.edge_mask.empty()) reference = render_cartoon_reference(scene, settings);
          row.edges = compare_edge_masks(reference.edge_mask, settings.width_px, settings.height_px, request.edges_png);
        } else {
          const AovFrame ids = render_aov_frame(scene, settings, {AovKind::PrimitiveId});
          row.ids = compare_primitive_ids(*ids.surfaces[0], request.primitive_ids_exr);
          if (!o.keep.empty()) {
            write_exr_channels(work / (stem + "_ontile_ids.exr"), settings.width_px, settings.height_px,
                               aov_channel_names(AovKind::PrimitiveId),
                               aov_channels(*ids.surfaces[0], AovKind::PrimitiveId));
          }
        }
        if (!o.keep.empty()) {
          write_png_rgba8(work / (stem + "_ontile.png"), settings.width_px, settings.height_px,
                          last.outputs.color->bytes());
          if (cartoon) {
            std::vector<uint8_t> rgba(reference.edge_mask.size() * 4, 255);
            for (size_t i = 0; i < reference.edge_mask.size(); ++i) {
              rgba[i * 4] = rgba[i * 4 + 1] = rgba[i * 4 + 2] = reference.edge_mask[i] ? 255 : 0;
            }
            write_png_rgba8(work / (stem + "_ontile_edges.png"), settings.width_px, settings.height_px, rgba);
          }
        }
        std::printf("%s", peer_row_line(row).c_str());
        std::fflush(stdout);
        rows.push_back(row);
      }
    }
    if (!ps.generator.empty() && o.keep.empty()) fs::remove(file);
  }

  std::string text;
  for (const std::string& pipeline : pipelines) {
    text += "\n" + pipeline + " at " + std::to_string(settings.width_px) + "x" + std::to_string(settings.height_px) +
            ", median of " + std::to_string(o.frames) +
            " frames after 1 warm-up; CPU = process CPU ms per frame; ratios = ontile / llvmpipe\n" +
            peer_table(rows, pipeline, false);
  }
  std::printf("%s", text.c_str());
  if (!o.markdown.empty()) {
    const std::string commit =
        first_line_of_command("git -C '" + std::string(ONTILE_SOURCE_DIR) + "' describe --always --dirty 2>/dev/null");
    const std::string cpu = first_line_of_command("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'");
    std::ostringstream md;
    md << "Median of " << o.frames << " frames after 1 warm-up at " << settings.width_px << "x" << settings.height_px
       << "; ontile commit " << commit << "; " << renderer << "; CPU " << cpu << " ("
       << sysconf(_SC_NPROCESSORS_ONLN) << " logical cores); load average (1, 5, 15 min) " << load_before
       << " before the run, " << first_line_of_command("cut -d' ' -f1-3 /proc/loadavg")
       << " after. CPU ms: process CPU time per frame, all threads.\n";
    for (const std::string& pipeline : pipelines) md << "\n### " << pipeline << "\n\n" << peer_table(rows, pipeline, true);
    const fs::path path(o.markdown);
    if (path.has_parent_path()) fs::create_directories(path.parent_path());
    write_file_atomically(path, [&](const fs::path& tmp) {
      std::ofstream f(tmp, std::ios::binary);
      f << md.str();
      if (!f) throw Error(path.string() + ": cannot write");
    });
    std::printf("wrote %s\n", o.markdown.c_str());
  }
}

}  // namespace
}  // namespace ontile::peer

int main(int argc, char** argv) {
  CLI::App app{"ontile_peer_bench: ontile's lambert and cartoon frames against Mesa llvmpipe (frame times, "
               "agreement)"};
  ontile::peer::Options o;
  app.add_option("--frames", o.frames, "Timed frames per run after one warm-up (default 5)")->check(CLI::Range(1, 100000));
  app.add_option("--scenes", o.scenes, "Comma-separated: atrium, atrium-2m, ToyCar, DamagedHelmet, demo (default all)");
  app.add_option("--size", o.size, "Image size WIDTHxHEIGHT (default 1920x1080)");
  app.add_option("--threads", o.threads, "Comma-separated thread counts (default 1,2)");
  app.add_option("--pipelines", o.pipelines, "Comma-separated: lambert, cartoon (default both)");
  app.add_option("--markdown", o.markdown, "Also write the table as Markdown to this file");
  app.add_option("--llvmpipe", o.llvmpipe, "The llvmpipe runner (default: the one built with this program)");
  app.add_option("--keep", o.keep, "Keep both renderers' images, primitive-id EXRs and edge masks in this folder");
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
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
