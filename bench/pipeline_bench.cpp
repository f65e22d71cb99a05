// Pipeline comparison (issue 4): every cartoon pipeline and `universal` on the demo scene, the
// atrium, DamagedHelmet and ToyCar at 1920x1080 on 2 threads. Reports the median frame time
// and, as counters, the frame's external bytes read and written (deterministic).
#include <benchmark/benchmark.h>

#include "bench_scenes.h"
#include "pipeline_bench.h"
#include "pipelines/kit/pipeline.h"
#include "pipelines/kit/render_frame.h"
#include "util/error.h"

namespace ontile {
namespace {

const Scene* scene_named(const std::string& name) {
  if (name == "demo") return bench::file_scene(std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb");
  if (name == "atrium") return bench::generated_scene("atrium", 1.0);
  if (name == "DamagedHelmet") return bench::shared_asset("DamagedHelmet/DamagedHelmet.glb");
  return bench::shared_asset("ToyCar/ToyCar.gltf");
}

void pipeline_benchmark(benchmark::State& state, const std::string& scene_name, const std::string& pipeline) {
  const Scene* scene = scene_named(scene_name);
  if (!scene) {
    state.SkipWithError("scene not available (../shared/assets missing?)");
    return;
  }
  RenderSettings settings;
  settings.pipeline = pipeline;
  settings.width_px = 1920;
  settings.height_px = 1080;
  settings.context.threads = 2;
  uint64_t read = 0, written = 0;
  for (auto _ : state) {
    const RenderedFrame frame = render_frame(*scene, settings);
    state.SetIterationTime(frame.outputs.report.total_ms / 1000.0);
    read = frame.outputs.report.bytes_read();
    written = frame.outputs.report.bytes_written();
  }
  state.counters["read_MB"] = read / 1e6;
  state.counters["written_MB"] = written / 1e6;
}

}  // namespace

// Registered from main: the pipelines register themselves from static objects of another library
// (pipelines/kit/pipeline.h), so a static initialiser here could run before them and find none,
// which silently dropped every Pipeline/* benchmark from d524702 to session 14.
void register_pipeline_benchmarks() {
  const std::vector<std::string> pipelines = pipeline_names();
  if (pipelines.empty()) throw Error("no pipeline registered: the Pipeline/* benchmarks would be missing");
  for (const std::string scene : {"demo", "atrium", "DamagedHelmet", "ToyCar"}) {
    for (const std::string& pipeline : pipelines) {
      benchmark::RegisterBenchmark(("Pipeline/" + scene + "/" + pipeline).c_str(),
                                   [scene, pipeline](benchmark::State& s) { pipeline_benchmark(s, scene, pipeline); })
          ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3)
          ->ReportAggregatesOnly(true);
    }
  }
}

}  // namespace ontile
