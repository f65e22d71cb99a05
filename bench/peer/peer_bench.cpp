// ontile_peer_bench: ontile's lambert frame against Mesa llvmpipe (bench/llvmpipe/) on the same
// scenes, camera, size and shading; frame-time table per scene and thread count, and how many
// pixels show the same triangle (primitive-id AOVs) and the same colour in both renderers.
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
#include "peer_child.h"
#include "peer_compare.h"
#include "pipelines/aov/aov_pass.h"
#include "pipelines/render_frame.h"
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
  std::string scenes = "atrium,atrium-2m,ToyCar,DamagedHelmet", size = "1920x1080", threads = "1,2";
  std::string markdown, llvmpipe = ONTILE_LLVMPIPE_RUNNER, keep;
};

// A benchmark scene: generated (written to a temporary .glb the child can load) or a file of
// ../shared/assets.
struct PeerScene {
  std::string name;
  double generated_size = 0.0;  // > 0: bench::generated_scene("atrium", size)
  std::string shared_relative;
};

const std::vector<PeerScene> kScenes = {{"atrium", 1.0, ""},
                                        {"atrium-2m", 8.0, ""},
                                        {"ToyCar", 0.0, "ToyCar/ToyCar.gltf"},
                                        {"DamagedHelmet", 0.0, "DamagedHelmet/DamagedHelmet.glb"}};

struct Row {
  std::string scene;
  uint64_t triangles = 0;
  int threads = 0;
  FrameTimes ontile, llvmpipe;
  IdAgreement ids;
  ColorAgreement color;
};

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
    if (!found) throw Error("--scenes '" + name + "': unknown scene (atrium, atrium-2m, ToyCar, DamagedHelmet)");
  }
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

// Two ratios: of the median wall times, and of the CPU times per frame (all threads), which
// other work on the machine disturbs much less.
std::string table(const std::vector<Row>& rows, bool markdown) {
  std::string out;
  char line[512];
  if (markdown) {
    out += "| scene | triangles | threads | ontile median ms | ontile min ms | ontile CPU ms | "
           "llvmpipe median ms | llvmpipe min ms | llvmpipe CPU ms | ontile / llvmpipe (median) | "
           "ontile / llvmpipe (CPU) | primitive ids equal | colour within 2/255 |\n"
           "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  } else {
    std::snprintf(line, sizeof line, "%-14s %9s %7s | %10s %8s %8s | %10s %8s %8s | %6s %6s | %10s %9s\n", "scene",
                  "triangles", "threads", "ontile med", "min", "CPU", "llvmpipe", "min", "CPU", "ratio", "CPU",
                  "ids equal", "colour ok");
    out += line;
  }
  for (const Row& r : rows) {
    const char* fmt = markdown
        ? "| %s | %llu | %d | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f | %.2f | %.3f %% | %.2f %% |\n"
        : "%-14s %9llu %7d | %10.1f %8.1f %8.1f | %10.1f %8.1f %8.1f | %6.2f %6.2f | %9.3f%% %8.2f%%\n";
    std::snprintf(line, sizeof line, fmt, r.scene.c_str(), static_cast<unsigned long long>(r.triangles), r.threads,
                  r.ontile.median_ms, r.ontile.min_ms, r.ontile.cpu_ms_per_frame, r.llvmpipe.median_ms,
                  r.llvmpipe.min_ms, r.llvmpipe.cpu_ms_per_frame, r.ontile.median_ms / r.llvmpipe.median_ms,
                  r.ontile.cpu_ms_per_frame / r.llvmpipe.cpu_ms_per_frame, r.ids.percent(), r.color.percent());
    out += line;
  }
  return out;
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

  std::vector<Row> rows;
  std::string renderer;
  for (const PeerScene& ps : scenes) {
    fs::path file;
    if (ps.generated_size > 0.0) {
      file = work / ("generated_" + ps.name + ".glb");
      SceneGenOptions gen;
      gen.size = ps.generated_size;
      generate_scene("atrium", gen, file);
    } else {
      file = fs::path(ONTILE_SHARED_ASSETS) / ps.shared_relative;
      if (!fs::exists(file)) {
        std::printf("skipping %s: %s not found\n", ps.name.c_str(), file.string().c_str());
        continue;
      }
    }
    const Scene scene = load_gltf(file);
    for (int t : threads) {
      Row row;
      row.scene = ps.name;
      row.triangles = scene.drawn_triangle_count();
      row.threads = t;
      settings.context.threads = t;
      RenderedFrame last;
      row.ontile = time_ontile(scene, settings, o.frames, last);
      const AovFrame ids = render_aov_frame(scene, settings, {AovKind::PrimitiveId});
      const std::string stem = ps.name + "_t" + std::to_string(t);
      LlvmpipeRequest request{o.llvmpipe, file, settings.width_px, settings.height_px, o.frames, t,
                              work / (stem + "_llvmpipe.png"), work / (stem + "_llvmpipe_ids.exr")};
      const LlvmpipeRun child = run_llvmpipe(request);
      renderer = child.renderer;
      row.llvmpipe = child.times;
      row.ids = compare_primitive_ids(*ids.surfaces[0], request.primitive_ids_exr);
      row.color = compare_colors(*last.outputs.color, request.color_png);
      if (!o.keep.empty()) {
        write_png_rgba8(work / (stem + "_ontile.png"), settings.width_px, settings.height_px,
                        last.outputs.color->bytes());
        write_exr_channels(work / (stem + "_ontile_ids.exr"), settings.width_px, settings.height_px,
                           aov_channel_names(AovKind::PrimitiveId),
                           aov_channels(*ids.surfaces[0], AovKind::PrimitiveId));
      }
      std::printf("%s, %d thread(s): ontile %.1f ms, llvmpipe %.1f ms (medians; %.2f and %.2f cores busy); "
                  "primitive ids equal on "
                  "%.3f%% (%llu pixels differ in coverage, %llu in id, of which %llu are boundaries shifted by "
                  "a pixel); colour within %d/255 on %.2f%% (mean |diff| %.3f)\n",
                  ps.name.c_str(), t, row.ontile.median_ms, row.llvmpipe.median_ms, row.ontile.cores_busy,
                  row.llvmpipe.cores_busy, row.ids.percent(),
                  static_cast<unsigned long long>(row.ids.coverage_differs),
                  static_cast<unsigned long long>(row.ids.id_differs),
                  static_cast<unsigned long long>(row.ids.boundary_shifts), kColorTolerance, row.color.percent(),
                  row.color.mean_abs_diff);
      std::fflush(stdout);
      rows.push_back(row);
    }
    if (ps.generated_size > 0.0 && o.keep.empty()) fs::remove(file);
  }

  std::printf("\nlambert at %dx%d, median of %d frames after 1 warm-up; CPU = process CPU ms per frame; ratios = "
              "ontile / llvmpipe\n%s",
              settings.width_px, settings.height_px, o.frames, table(rows, false).c_str());
  if (!o.markdown.empty()) {
    const std::string commit =
        first_line_of_command("git -C '" + std::string(ONTILE_SOURCE_DIR) + "' describe --always --dirty 2>/dev/null");
    const std::string cpu = first_line_of_command("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'");
    std::ostringstream md;
    md << "lambert at " << settings.width_px << "x" << settings.height_px << ", median of " << o.frames
       << " frames after 1 warm-up; ontile commit " << commit << "; " << renderer << "; CPU " << cpu << " ("
       << sysconf(_SC_NPROCESSORS_ONLN) << " logical cores); load average (1, 5, 15 min) " << load_before
       << " before the run, " << first_line_of_command("cut -d' ' -f1-3 /proc/loadavg")
       << " after. CPU ms: process CPU time per frame, all threads.\n\n"
       << table(rows, true);
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
  CLI::App app{"ontile_peer_bench: ontile's lambert frame against Mesa llvmpipe (frame times, primitive ids)"};
  ontile::peer::Options o;
  app.add_option("--frames", o.frames, "Timed frames per run after one warm-up (default 5)")->check(CLI::Range(1, 100000));
  app.add_option("--scenes", o.scenes, "Comma-separated: atrium, atrium-2m, ToyCar, DamagedHelmet (default all)");
  app.add_option("--size", o.size, "Image size WIDTHxHEIGHT (default 1920x1080)");
  app.add_option("--threads", o.threads, "Comma-separated thread counts (default 1,2)");
  app.add_option("--markdown", o.markdown, "Also write the table as Markdown to this file");
  app.add_option("--llvmpipe", o.llvmpipe, "The llvmpipe runner (default: the one built with this program)");
  app.add_option("--keep", o.keep, "Keep both renderers' images and primitive-id EXRs in this folder");
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
