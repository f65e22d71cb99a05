// The texture-cache replay alone (issue 11, item 1): the texel traces of every pass of a real
// frame, captured once through the replay observer, then replayed through a fresh frame cache per
// iteration, passes in order, on one thread (the serial / streamed replay's kernel). Reports the
// time per traced access, so changes to the replay are measured without the tiles around them.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench_scenes.h"
#include "memory/texture_replay_observer.h"
#include "pipelines/kit/render_frame.h"

namespace ontile {
namespace {

// Every pass's traces, in replay order, and the cache shape they were replayed through.
struct CapturedFrame {
  TextureCacheConfig cache;
  std::vector<std::vector<TileTrace>> passes;
  uint64_t accesses = 0, misses = 0;
};

class TraceCapture : public TextureReplayObserver {
 public:
  explicit TraceCapture(CapturedFrame& frame) : frame_(frame) {}
  void before_replay(const TextureCache&) override {}
  void after_replay(const TextureCache& cache, const std::vector<TileTrace>& traces,
                    const TextureTraffic& traffic) override {
    frame_.cache = cache.config();
    frame_.passes.push_back(traces);
    frame_.accesses += traffic.accesses;
    frame_.misses += traffic.misses;
  }

 private:
  CapturedFrame& frame_;
};

// Renders `pipeline` on `scene` at 1920x1080 once and keeps its traces (null scene: none).
std::unique_ptr<CapturedFrame> capture(const Scene* scene, const std::string& pipeline) {
  if (!scene) return nullptr;
  auto frame = std::make_unique<CapturedFrame>();
  TraceCapture observer(*frame);
  set_texture_replay_observer(&observer);
  RenderSettings settings;
  settings.pipeline = pipeline;
  settings.width_px = 1920;
  settings.height_px = 1080;
  settings.context.threads = 1;
  render_frame(*scene, settings);
  set_texture_replay_observer(nullptr);
  return frame;
}

void replay_benchmark(benchmark::State& state, const CapturedFrame* frame) {
  if (!frame) {
    state.SkipWithError("scene not available (../shared/assets missing?)");
    return;
  }
  uint64_t misses = 0;
  for (auto _ : state) {
    TextureCache cache(frame->cache);
    misses = 0;
    for (const std::vector<TileTrace>& pass : frame->passes) misses += replay_texture_traces(cache, pass).misses;
  }
  if (misses != frame->misses) state.SkipWithError("the replay's misses differ from the frame's");
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * frame->accesses));
  state.counters["accesses_M"] = static_cast<double>(frame->accesses) / 1e6;
  state.counters["ns_per_access"] = benchmark::Counter(
      static_cast<double>(frame->accesses), benchmark::Counter::kIsIterationInvariantRate |
                                                benchmark::Counter::kInvert);
}

const CapturedFrame* captured(const std::string& key, const Scene* scene, const std::string& pipeline) {
  static std::map<std::string, std::unique_ptr<CapturedFrame>> frames;
  auto& slot = frames[key];
  if (!slot) slot = capture(scene, pipeline);
  return slot.get();
}

void BM_ReplayDemoCartoon(benchmark::State& s) {
  replay_benchmark(s, captured("demo-cartoon", bench::generated_scene("demo", 1.0), "cartoon"));
}
void BM_ReplayDemoUniversal(benchmark::State& s) {
  replay_benchmark(s, captured("demo-universal", bench::generated_scene("demo", 1.0), "universal"));
}
void BM_ReplayAtriumLambert(benchmark::State& s) {
  replay_benchmark(s, captured("atrium-lambert", bench::generated_scene("atrium", 1.0), "lambert"));
}
void BM_ReplayAtriumUniversal(benchmark::State& s) {
  replay_benchmark(s, captured("atrium-universal", bench::generated_scene("atrium", 1.0), "universal"));
}
void BM_ReplayHelmetLambert(benchmark::State& s) {
  replay_benchmark(s, captured("helmet-lambert", bench::shared_asset("DamagedHelmet/DamagedHelmet.glb"), "lambert"));
}

BENCHMARK(BM_ReplayDemoCartoon)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_ReplayDemoUniversal)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_ReplayAtriumLambert)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_ReplayAtriumUniversal)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_ReplayHelmetLambert)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace
}  // namespace ontile
