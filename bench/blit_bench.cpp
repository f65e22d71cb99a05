// The full-screen copy against the machine's limit (issue 11): a 1920x1080 RGBA8 render target
// copied by a blit through tile memory (snapshot, full-screen triangle, copy functor, texel
// trace and texture-cache model, tile store), against std::memcpy of the same 8,294,400 bytes.
// Medians of repetitions; the ratio is blit time over memcpy time from one run.
#include <benchmark/benchmark.h>

#include <cstring>
#include <memory>
#include <vector>

#include "context/command_buffer.h"
#include "context/render_context.h"
#include "pipelines/universal/post_processing.h"

namespace ontile {
namespace {

constexpr int kWidthPx = 1920, kHeightPx = 1080;
constexpr size_t kBytes = size_t{4} * kWidthPx * kHeightPx;

void BM_MemcpyRgba8_1080p(benchmark::State& state) {
  std::vector<uint8_t> source(kBytes), destination(kBytes);
  for (size_t i = 0; i < kBytes; ++i) source[i] = static_cast<uint8_t>(i * 2654435761u >> 24);
  for (auto _ : state) {
    std::memcpy(destination.data(), source.data(), kBytes);
    benchmark::DoNotOptimize(destination.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * kBytes));
}

// Every iteration records and submits one blit; the time is the whole submit (snapshot of the
// source, binning the full-screen triangle, the tiles, the texture-cache replay).
void BM_BlitCopyRgba8_1080p(benchmark::State& state) {
  ContextConfig config;
  config.threads = static_cast<int>(state.range(0));
  RenderContext context(config);
  Surface* source = context.create_surface("source", PixelFormat::RGBA8_UNORM, kWidthPx, kHeightPx);
  Surface* destination =
      context.create_surface("destination", PixelFormat::RGBA8_UNORM, kWidthPx, kHeightPx);
  for (int y = 0; y < kHeightPx; ++y) {
    for (int x = 0; x < kWidthPx; ++x) {
      source->write(x, y, 0, glm::vec4((x & 255) / 255.0f, (y & 255) / 255.0f, 0.5f, 1.0f));
    }
  }
  const std::unique_ptr<Shader> blit_shader = make_universal_blit_shader();
  const std::unique_ptr<RenderMaterial> copy = make_copy_material(*blit_shader, "copy");
  uint64_t texture_bytes = 0;
  for (auto _ : state) {
    CommandBuffer commands;
    commands.blit(RenderTargetRef::of(source), RenderTargetRef::of(destination), copy.get(), "Copy");
    context.execute_command_buffer(commands);
    const FrameReport report = context.submit();
    texture_bytes = report.passes.at(0).texture.bytes_read;
  }
  if (destination->bytes() != source->bytes()) state.SkipWithError("the copy differs from its source");
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * kBytes));
  state.counters["texture_MiB"] = static_cast<double>(texture_bytes) / (1024.0 * 1024.0);
}

BENCHMARK(BM_MemcpyRgba8_1080p)->Unit(benchmark::kMillisecond)->Repetitions(7)->ReportAggregatesOnly(true);
BENCHMARK(BM_BlitCopyRgba8_1080p)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)
    ->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace
}  // namespace ontile
