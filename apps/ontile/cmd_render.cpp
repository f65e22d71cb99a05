// `ontile render`: renders a scene with a pipeline, writes the image (and optionally the JSON
// traffic report, "-" for standard output; the HTML report and attachment dumps) together, and
// prints a summary with the traffic table; --frames N times N frames.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "commands.h"
#include "aov/aov_pass.h"
#include "context/frame_report.h"
#include "io/image_io.h"
#include "memory/transaction_elimination.h"
#include "pipelines/kit/render_frame.h"
#include "render_inspect.h"
#include "render_report.h"
#include "scene/gltf_loader.h"
#include "tiler/gpu_presets.h"
#include "util/error.h"
#include "util/heap_tuning.h"

namespace ontile::cli {
namespace {

struct RenderOptions {
  std::string scene, out, report, size = "1280x720", pipeline = "lambert", arch = "tbdr", aov, gbuffer, lights,
              render_graph = "off", afbc = "off", transaction_elimination = "off", gpu, idvs = "off",
              varying_precision = "fp32", texture_compression = "none";
  double camera_pan_deg = 0.0;  // --camera-pan: degrees the camera turns per frame
  bool allow_outside_files = false, progress = false, tiles = false;
  int camera = -1, threads = 0, tile = 16, budget = 128, subpixel_bits = 8;
  int texture_cache_kib = 256, rt_cache_kib = 128, parameter_cache_kib = 0;
  std::vector<std::string> pipeline_options;
  std::optional<int> frames;  // --frames: time this many frames after a warm-up
  InspectOptions inspect;     // --html, --dump-attachments, --tile-grid
  std::vector<std::string> given;  // the tiler options given explicitly (they override --gpu)
  bool was_given(const std::string& option) const {
    return std::find(given.begin(), given.end(), option) != given.end();
  }
};

// The options a --gpu preset sets, which an explicit one overrides.
const std::vector<std::string> kPresetOptions = {"--tile", "--budget", "--afbc", "--transaction-elimination",
                                                 "--idvs", "--texture-cache-kib", "--parameter-cache-kib"};

// Renders once (the warm-up when timing), then `frames` more times with each frame timed by the
// wall clock of the whole render call; returns the last frame. Progress counts the timed frames.
template <class Render>
auto render_timed(int frames, std::vector<double>& ms, bool show_progress, Render&& render) {
  Progress progress("render", show_progress);
  if (frames) progress.step(0, frames, "warm-up frame");
  auto frame = render();
  for (int i = 0; i < frames; ++i) {
    progress.step(i + 1, frames, "timed frame");
    const auto start = std::chrono::steady_clock::now();
    frame = render();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return frame;
}

// The same three lines as bench/llvmpipe's runner prints, so scripts read both alike.
void print_frame_times(std::FILE* stream, std::vector<double> ms) {
  if (ms.empty()) return;
  std::sort(ms.begin(), ms.end());
  const size_t n = ms.size();
  const double median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
  std::fprintf(stream, "frames: %zu after 1 warm-up\nmedian_ms: %.3f\nmin_ms: %.3f\n", n, median, ms.front());
}

void write_color(const std::filesystem::path& path, const Surface& color, StagedOutputs& staged) {
  const std::string ext = path.extension().string();
  if (ext == ".png") {
    if (color.format() != PixelFormat::RGBA8_SRGB && color.format() != PixelFormat::RGBA8_UNORM) {
      throw Error(path.string() + ": PNG needs an 8-bit target, the pipeline produced " +
                  format_name(color.format()));
    }
    write_png_rgba8(path, color.width(), color.height(), color.bytes(), &staged);
  } else if (ext == ".exr") {
    ImageRGBA32F image;
    image.width = color.width();
    image.height = color.height();
    image.pixels.reserve(static_cast<size_t>(image.width) * image.height * 4);
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const glm::vec4 v = color.read(x, y);
        image.pixels.insert(image.pixels.end(), {v.x, v.y, v.z, v.w});
      }
    }
    write_image(path, image, false, &staged);
  } else {
    throw UsageError("--out " + path.string() + ": unsupported output extension '" + ext + "' (use .png or .exr)");
  }
}

RenderRun run_of(const RenderOptions& o, const RenderSettings& settings) {
  return {o.scene, settings, o.aov, o.frames, o.tiles, o.gpu, *parse_texture_compression(o.texture_compression)};
}

// --aov: the AOV pass instead of the pipeline's image, written as a float EXR (with
// --set msaa=N, each pixel's sample 0: aov_pass.h).
void run_aov_render(const RenderOptions& o, const RenderSettings& settings, RunOutputs& outputs) {
  const AovKind kind = *parse_aov_kind(o.aov);
  const Scene scene = load_scene(o.scene, o.allow_outside_files, *parse_texture_compression(o.texture_compression));
  std::vector<double> ms;
  const AovFrame frame =
      render_timed(o.frames.value_or(0), ms, o.progress, [&] { return render_aov_frame(scene, settings, {kind}); });
  write_exr_channels(o.out, settings.width_px, settings.height_px, aov_channel_names(kind),
                     aov_channels(*frame.surfaces[0], kind), &outputs.files());
  if (!o.report.empty()) outputs.text(o.report, render_report_json(frame.report, run_of(o, settings)).dump(2) + "\n");
  outputs.commit();
  std::FILE* summary = summary_stream(is_stdout(o.report));
  std::fprintf(summary, "%s: %dx%d, AOV %s, %d samples per pixel (sample 0 written), %.1f ms on %d threads\n",
               o.scene.c_str(), settings.width_px, settings.height_px, o.aov.c_str(), frame.report.passes[0].samples,
               frame.report.total_ms, frame.report.threads);
  std::fprintf(summary, "wrote %s%s%s\n", o.out.c_str(), o.report.empty() ? "" : " and ", o.report.c_str());
  print_frame_times(summary, ms);
}

// The summary line: tiles are what a TBDR pass executes; an IMR pass has none to report (its
// traffic model is the render-target cache, shown in the table).
void print_summary(std::FILE* out, const RenderOptions& o, const RenderSettings& settings, const Scene& scene,
                   const FrameReport& report) {
  uint64_t binned = 0, tiles = 0, non_finite = 0;
  for (const PassReport& p : report.passes) {
    binned += p.geometry.triangles_binned;
    tiles += p.tiles_total;
    non_finite += p.geometry.triangles_non_finite;
  }
  const bool imr = settings.context.tiler.architecture == Architecture::Imr;
  std::fprintf(out, "%s: %dx%d, pipeline %s, %llu triangles in the scene", o.scene.c_str(), settings.width_px,
               settings.height_px, o.pipeline.c_str(), static_cast<unsigned long long>(scene.drawn_triangle_count()));
  if (imr) {
    std::fprintf(out, ", immediate mode (IMR)");
  } else {
    std::fprintf(out, " (%llu binned), %llu tiles", static_cast<unsigned long long>(binned),
                 static_cast<unsigned long long>(tiles));
  }
  std::fprintf(out, ", %.1f ms on %d threads\n", report.total_ms, report.threads);
  if (non_finite) {
    std::fprintf(out, "warning: dropped %llu triangles with NaN/Inf positions\n",
                 static_cast<unsigned long long>(non_finite));
  }
  std::fprintf(out, "external traffic: %llu bytes read, %llu bytes written\n",
               static_cast<unsigned long long>(report.bytes_read()),
               static_cast<unsigned long long>(report.bytes_written()));
  std::fputs(frame_report_table(report).c_str(), out);
}

// --gpu: the preset's settings, then the tiler options given explicitly on top of them.
// Transaction elimination needs 16x16 tiles (panfrost, pan_select_crc_rt): other sizes are refused.
void apply_gpu_option(const RenderOptions& o, TilerConfig& tiler) {
  if (!o.gpu.empty()) {
    const GpuPreset* preset = find_gpu_preset(o.gpu);
    if (!preset) throw UsageError("--gpu " + o.gpu + ": expected one of " + gpu_preset_names());
    const TilerConfig given = tiler;
    apply_gpu_preset(*preset, tiler);
    if (o.was_given("--tile")) tiler.tile_size_px = given.tile_size_px;
    if (o.was_given("--budget")) tiler.color_budget_bits_per_px = given.color_budget_bits_per_px;
    if (o.was_given("--afbc")) tiler.afbc = given.afbc;
    if (o.was_given("--transaction-elimination")) tiler.transaction_elimination = given.transaction_elimination;
    if (o.was_given("--idvs")) tiler.idvs = given.idvs;
    if (o.was_given("--texture-cache-kib")) tiler.texture_cache = given.texture_cache;
    if (o.was_given("--parameter-cache-kib")) tiler.parameter_cache = given.parameter_cache;
  }
  const bool sixteen = tiler.tile_size_px == kTransactionEliminationTilePx &&
                       (tiler.tile_size_rule == TileSizeRule::Budget || tiler.tile_size_rule == TileSizeRule::Panfrost);
  if (tiler.transaction_elimination && !sixteen) {
    throw UsageError("--transaction-elimination needs 16x16 tiles (CRCs per 16x16 tile, as panfrost), but the "
                     "tiles are " + (tiler.tile_size_rule == TileSizeRule::Budget
                                         ? std::to_string(tiler.tile_size_px) + "x" + std::to_string(tiler.tile_size_px)
                                         : "chosen by --gpu " + o.gpu));
  }
}

// Everything that can be checked before loading the scene: a usage error costs no render.
RenderSettings checked_settings(const RenderOptions& o) {
  if (o.frames && *o.frames < 1) {
    throw UsageError("--frames " + std::to_string(*o.frames) + ": expected a frame count >= 1");
  }
  RenderSettings settings;
  parse_size(o.size, settings.width_px, settings.height_px);
  try {
    make_pipeline(o.pipeline);
  } catch (const Error& e) {
    throw UsageError(std::string("--pipeline: ") + e.what());
  }
  settings.pipeline = o.pipeline;
  settings.camera_index = o.camera;
  for (const std::string& kv : o.pipeline_options) {
    const size_t eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw UsageError("--set '" + kv + "': expected KEY=VALUE");
    settings.options.set(kv.substr(0, eq), kv.substr(eq + 1));
  }
  // Shorthands for the forward and deferred pipelines' options (an unknown option is still an
  // error for pipelines without them).
  if (!o.gbuffer.empty()) settings.options.set("gbuffer", o.gbuffer);
  if (!o.lights.empty()) settings.options.set("lights", o.lights);
  settings.context.threads = o.threads;
  settings.context.tiler.tile_size_px = o.tile;
  settings.context.tiler.color_budget_bits_per_px = o.budget;
  settings.context.tiler.subpixel_bits = o.subpixel_bits;
  settings.context.tiler.architecture = o.arch == "imr" ? Architecture::Imr : Architecture::Tbdr;
  settings.context.render_graph = parse_render_graph_mode(o.render_graph);
  settings.context.tiler.texture_cache.size_bytes = static_cast<uint32_t>(o.texture_cache_kib) * 1024;
  settings.context.tiler.parameter_cache.size_bytes = static_cast<uint32_t>(o.parameter_cache_kib) * 1024;
  settings.context.tiler.render_target_cache.size_bytes = static_cast<uint32_t>(o.rt_cache_kib) * 1024;
  settings.context.tiler.afbc = o.afbc == "on";
  if (o.transaction_elimination != "off") {
    settings.context.tiler.transaction_elimination =
        std::make_shared<TileSignatureHistory>(*parse_crc_targets(o.transaction_elimination));
  }
  settings.context.tiler.idvs = o.idvs == "on";
  settings.context.tiler.varying_precision =
      o.varying_precision == "fp16" ? VaryingPrecision::Fp16 : VaryingPrecision::Fp32;
  apply_gpu_option(o, settings.context.tiler);
  settings.camera_pan_deg_per_frame = o.camera_pan_deg;
  const std::string ext = std::filesystem::path(o.out).extension().string();
  if (ext != ".png" && ext != ".exr") {
    throw UsageError("--out " + o.out + ": unsupported output extension '" + ext + "' (use .png or .exr)");
  }
  if (!o.aov.empty() && ext != ".exr") {
    throw UsageError("--out " + o.out + ": --aov writes float channels; use an .exr output");
  }
  if (!o.aov.empty() && o.pipeline != "lambert") {
    throw UsageError("--aov: AOVs are rendered with the lambert pipeline's geometry; --pipeline " + o.pipeline +
                     " has none");
  }
  check_output_option("--out", o.out, false);
  if (!o.report.empty()) check_output_option("--report", o.report, true);
  check_inspect_options(o.inspect, !o.aov.empty());
  check_distinct_outputs({{"--out", o.out}, {"--report", o.report}, {"--html", o.inspect.html}});
  return settings;
}

void run_render(const RenderOptions& o) {
  const RenderSettings settings = checked_settings(o);
  // Steady-state frame times: the frames reuse the heap instead of fresh pages (heap_tuning.h).
  if (o.frames) keep_freed_memory_in_the_heap();
  RunOutputs outputs;
  if (!o.aov.empty()) {
    run_aov_render(o, settings, outputs);
    return;
  }
  const Scene scene = load_scene(o.scene, o.allow_outside_files, *parse_texture_compression(o.texture_compression));
  std::vector<double> ms;
  // --html and --dump-attachments capture every pass of the first (warm-up) frame: frames are
  // bit-identical, and the timed frames then pay nothing for the copies.
  PassCapture capture;
  bool first_frame = true;
  int frame_index = 0;
  const RenderedFrame frame = render_timed(o.frames.value_or(0), ms, o.progress, [&] {
    RenderSettings frame_settings = settings;
    if (first_frame && o.inspect.wanted()) frame_settings.context.pass_observer = &capture;
    first_frame = false;
    frame_settings.frame_index = frame_index++;
    return render_frame(scene, frame_settings);
  });
  const FrameReport& report = frame.outputs.report;
  write_color(o.out, *frame.outputs.color, outputs.files());
  const nlohmann::json json = render_report_json(report, run_of(o, settings));
  if (!o.report.empty()) outputs.text(o.report, json.dump(2) + "\n");
  const std::string title = o.scene + ": " + o.pipeline + ", " + std::to_string(settings.width_px) + "x" +
                            std::to_string(settings.height_px);
  const size_t dumped = o.inspect.wanted()
                            ? stage_inspection(o.inspect, frame.outputs, capture, json["run"], title, outputs.files())
                            : 0;
  outputs.commit();
  std::FILE* summary = summary_stream(is_stdout(o.report));
  print_summary(summary, o, settings, scene, report);
  if (settings.context.tiler.transaction_elimination && !o.frames) {
    std::fprintf(summary, "note: transaction elimination compares each frame with the previous one; with one frame it "
                          "eliminates nothing (render more with --frames N)\n");
  }
  std::fprintf(summary, "wrote %s%s%s\n", o.out.c_str(), o.report.empty() ? "" : " and ", o.report.c_str());
  if (!o.inspect.html.empty()) std::fprintf(summary, "wrote %s\n", o.inspect.html.c_str());
  if (!o.inspect.dump_dir.empty()) std::fprintf(summary, "wrote %zu attachment files into %s\n", dumped, o.inspect.dump_dir.c_str());
  print_frame_times(summary, ms);
}

}  // namespace

void add_render_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("render", "Render a glTF scene and report its memory traffic");
  auto o = std::make_shared<RenderOptions>();
  add_scene_options(cmd, o->scene, o->allow_outside_files, "glTF scene (.gltf or .glb)");
  cmd->add_option("--out", o->out, "Output image (.png or .exr)")->required();
  cmd->add_option("--pipeline", o->pipeline, "Render pipeline (see `ontile pipelines`)");
  cmd->add_option("--camera", o->camera, "Camera index in the scene (default: first camera, or a framing camera)")
      ->check(CLI::Range(0, 1 << 20));
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT, each side 1..16384 (default 1280x720)");
  cmd->add_option("--threads", o->threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--tile", o->tile, "Tile size in pixels")->check(CLI::IsMember({4, 8, 16, 32, 64}));
  cmd->add_option("--budget", o->budget, "Tile-memory colour budget in bits per pixel (default 128)")
      ->check(CLI::Range(32, 4096));
  cmd->add_option("--subpixel-bits", o->subpixel_bits, "Vertex snapping precision: 8 (D3D11, default) or 4 (Vulkan minimum)")
      ->check(CLI::IsMember({4, 8}));
  CLI::Option* report = cmd->add_option("--report", o->report, "Write the JSON traffic report here (- for standard output)");
  cmd->add_flag("--tiles", o->tiles,
                "Add per-tile statistics of every pass to the report: triangles, fragments, depth-killed "
                "fragments, cells, bytes per tile, and which thread ran each tile")
      ->needs(report);
  cmd->add_option("--aov", o->aov, "Write an AOV of the lambert geometry instead of the image (.exr; "
                                   "with --set msaa=N, each pixel's sample 0)")
      ->check(CLI::IsMember({"depth", "primitive_id", "normal"}));
  cmd->add_option("--gbuffer", o->gbuffer, "G-buffer layout of forward/deferred pipelines: unity, vulkan-samples, vulkan-samples-large, bjorge (= --set gbuffer=NAME)");
  cmd->add_option("--lights", o->lights, "Generated point lights for forward/deferred pipelines (= --set lights=N)");
  cmd->add_option("--frames", o->frames,
                  "Render N more frames after one warm-up and print their median and minimum time (ms); "
                  "the outputs are the last frame's");
  add_progress_flag(cmd, o->progress);
  cmd->add_option("--html", o->inspect.html,
                  "Write a self-contained HTML report: final image, pass graph, every attachment after every pass, "
                  "per-tile heatmaps, traffic tables (docs/report.md)");
  cmd->add_option("--dump-attachments", o->inspect.dump_dir,
                  "Write every attachment after every pass into this existing folder: <pass index>-<pass>-<attachment>.png "
                  "(8-bit formats) or .exr (float and depth formats)");
  cmd->add_flag("--tile-grid", o->inspect.tile_grid, "Draw the tile grid over the --dump-attachments files");
  cmd->add_option("--set", o->pipeline_options, "Pipeline option KEY=VALUE (repeatable; see docs)");
  cmd->add_option("--arch", o->arch, "Memory model: tbdr (tile-based, default) or imr (immediate mode)")
      ->check(CLI::IsMember({"tbdr", "imr"}));
  cmd->add_option("--render-graph", o->render_graph,
                  "How pipelines written as render graphs run: off (passes as written, default), cull "
                  "(unread passes and attachments removed) or merge (also subpasses, transient attachments, "
                  "derived load/store; docs/render-graph.md)")
      ->check(CLI::IsMember({"off", "cull", "merge"}));
  cmd->add_option("--parameter-cache-kib", o->parameter_cache_kib,
                  "Model an L2 (16-way, 64-byte lines) for parameter-buffer reads, in KiB (default 0: none)")
      ->check(CLI::Range(0, 65536));
  cmd->add_option("--texture-cache-kib", o->texture_cache_kib, "Texture cache size in KiB (16-way, 64-byte lines; default 256)")
      ->check(CLI::IsMember({16, 32, 64, 128, 256, 512, 1024, 2048}));
  cmd->add_option("--afbc", o->afbc,
                  "Arm Frame Buffer Compression: on prices single-sample colour attachments of up to 32 bits "
                  "per pixel at their compressed size (TBDR only; docs/memory-model.md); default off")
      ->check(CLI::IsMember({"on", "off"}));
  cmd->add_option("--transaction-elimination", o->transaction_elimination,
                  "on: a tile write whose CRC equals the previous frame's is skipped, for one colour target per "
                  "pass as Mali's framebuffer descriptor allows (Bifrost v7); single-target-passes: only in passes "
                  "with one colour target (Bifrost v6); every-target: every single-sample colour write (16x16 tiles "
                  "only; needs --frames N to have a previous frame; TBDR only; docs/memory-model.md); default off")
      ->check(CLI::IsMember([] {
        std::vector<std::string> values = crc_targets_names();
        values.push_back("off");
        return values;
      }()));
  cmd->add_option("--gpu", o->gpu,
                  "GPU preset: mali-g76, mali-g71 (16x16, 128 bpp, AFBC, transaction elimination, IDVS, 512 KiB L2), "
                  "panfrost, apple-g13, adreno-630 (those drivers' tile-size rules); explicit --tile, --budget, "
                  "--afbc, --transaction-elimination, --idvs and cache sizes override it (docs/fidelity.md)")
      ->check(CLI::IsMember(gpu_preset_list()));
  cmd->add_option("--camera-pan", o->camera_pan_deg,
                  "Turn the camera this many degrees about the vertical axis per frame (with --frames: a moving "
                  "camera, which defeats transaction elimination); default 0")
      ->check(CLI::Range(-180.0, 180.0));
  cmd->add_option("--idvs", o->idvs,
                  "Index-driven vertex shading: on writes varyings to the parameter buffer only for vertices of "
                  "triangles that survive culling, positions for all (TBDR only); default off")
      ->check(CLI::IsMember({"on", "off"}));
  cmd->add_option("--varying-precision", o->varying_precision,
                  "Stored varying size: fp32 (4 bytes per component, default) or fp16 (2); interpolation "
                  "stays fp32, so images do not change")
      ->check(CLI::IsMember({"fp32", "fp16"}));
  cmd->add_option("--texture-compression", o->texture_compression,
                  "Storage of the scene's textures for the texture cache: none (default), astc4x4 (1 byte per "
                  "texel), astc8x8 (0.25), etc2 (0.5, or 1 with alpha); sampling still reads the decoded texels")
      ->check(CLI::IsMember({"none", "astc4x4", "astc8x8", "etc2"}));
  cmd->add_option("--rt-cache-kib", o->rt_cache_kib, "IMR render-target cache size in KiB (16-way, 64-byte lines; default 128)")
      ->check(CLI::IsMember({16, 32, 64, 128, 256, 512, 1024, 2048}));
  cmd->callback([o, cmd] {
    for (const std::string& option : kPresetOptions) {
      if (cmd->count(option) > 0) o->given.push_back(option);
    }
    run_render(*o);
  });
}

}  // namespace ontile::cli
