// The Bjorge anchor (GPU Pro 5, "Bandwidth efficient graphics with ARM Mali GPUs"; docs/fidelity.md):
// deferred shading at 1920x1080 with RGB10A2 albedo, RGB10A2 normals, D24S8 depth and a 32-bit
// framebuffer moves 31.64 MB read and 39.55 MB written of framebuffer traffic per frame with
// multiple render targets, and 7.91 MB written with pixel local storage (MB = 2^20 bytes, one
// 1920x1080 target of 4 bytes per pixel being 7.91). ontile's `--gbuffer bjorge` reproduces
// them exactly as attachment bytes plus the G-buffer read back as textures.
#include <gtest/gtest.h>

#include <cmath>

#include "pipelines/kit/render_frame.h"
#include "support/wall_scene.h"

namespace ontile {
namespace {

constexpr int kWidth = 1920, kHeight = 1080;
constexpr uint64_t kTargetBytes = uint64_t{kWidth} * kHeight * 4;  // 8,294,400 B = 7.91 MiB

struct FramebufferTraffic {
  uint64_t read = 0, written = 0;
};

// Attachment loads, stores and resolves, and texture reads of render targets (the G-buffer
// sampled by classic deferred's lighting pass): the traffic Bjorge counts.
FramebufferTraffic framebuffer_traffic(const FrameReport& report) {
  FramebufferTraffic t;
  for (const PassReport& p : report.passes) {
    t.read += p.attachment_bytes_loaded();
    t.written += p.attachment_bytes_stored();
    for (const TextureSourceTraffic& source : p.texture_sources) {
      if (source.render_target) t.read += source.bytes_read;
    }
  }
  return t;
}

FrameReport render_bjorge(const std::string& pipeline) {
  RenderSettings s;
  s.pipeline = pipeline;
  s.width_px = kWidth;
  s.height_px = kHeight;
  s.context.threads = 2;
  s.options.set("gbuffer", "bjorge");
  s.options.set("lights", "4");
  return render_frame(test::wall_scene(), s).outputs.report;
}

double mib_2dp(uint64_t bytes) { return std::round(static_cast<double>(bytes) / (1 << 20) * 100.0) / 100.0; }

TEST(BjorgeAnchor, MultipleRenderTargetsRead4AndWrite5TargetsPixelLocalStorageWrites1) {
  const FrameReport mrt = render_bjorge("deferred-classic");
  const FramebufferTraffic classic = framebuffer_traffic(mrt);
  // G-buffer pass: light (ambient + emission), albedo, normal, depth stored; lighting pass:
  // light loaded and stored, albedo, normal and depth read as textures.
  EXPECT_EQ(classic.read, 4 * kTargetBytes);
  EXPECT_EQ(classic.written, 5 * kTargetBytes);
  EXPECT_EQ(mib_2dp(classic.read), 31.64);
  EXPECT_EQ(mib_2dp(classic.written), 39.55);
  for (const PassReport& p : mrt.passes) {
    for (const AttachmentTraffic& a : p.attachments) {
      EXPECT_EQ(a.bytes_stored % kTargetBytes, 0u) << p.name << " " << a.name << ": 4 bytes per pixel";
    }
  }

  const FramebufferTraffic on_tile = framebuffer_traffic(render_bjorge("deferred-subpass"));
  EXPECT_EQ(on_tile.read, 0u);
  EXPECT_EQ(on_tile.written, kTargetBytes);
  EXPECT_EQ(mib_2dp(on_tile.written), 7.91);
}

}  // namespace
}  // namespace ontile
