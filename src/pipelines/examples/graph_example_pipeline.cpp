// `graph-example`: the example pipeline of docs/context-api.md, a forward renderer written as a
// render graph: depth prepass, opaques, transparents, and a sky pass whose output nothing reads.
#include "pipelines/kit/pipeline_api.h"
#include "pipelines/lit/lit_shader.h"

namespace ontile {
namespace {

class GraphExamplePipeline final : public Pipeline {
 public:
  std::string name() const override { return "graph-example"; }
  std::string description() const override {
    return "docs/context-api.md's example: forward Lambert as a render graph (depth prepass, "
           "opaques, transparents, an unread sky target); try --render-graph merge";
  }

  FrameOutputs render(RenderContext& ctx, const FrameInputs& in) override {
    in.options.reject_unknown(name());  // this pipeline has no --set options
    const std::unique_ptr<Shader> lit = make_lit_shader();
    FrameKit kit(ctx, in);  // camera matrices, then renderers with lit materials, culled
    const CullingResults& culling = kit.cull([&](const Material& m) { return make_lit_material(*lit, m); });
    set_lighting_globals(ctx, main_directional_light(kit.scene()));

    RenderGraph graph;
    const int w = kit.width_px(), h = kit.height_px();
    const GraphResource color = graph.create({"color", PixelFormat::RGBA8_SRGB, w, h, 1, lit::kBackgroundColor});
    const GraphResource depth = graph.create({"depth", PixelFormat::D32_FLOAT, w, h, 1, glm::vec4(1.0f)});
    const GraphResource sky = graph.create({"sky", PixelFormat::RGBA8_UNORM, w, h});

    graph.add_pass("depth prepass")
        .write_depth(depth, LoadAction::Clear, StoreAction::Store)
        .record([&](GraphPassRecorder& r) {
          r.draw_renderers(culling, {{lit::kDepthOnly}, SortingCriteria::CommonOpaque}, {RenderQueueRange::opaque()});
        });
    graph.add_pass("opaques")
        .write_color(color, LoadAction::Clear, StoreAction::Store)
        .write_depth(depth, LoadAction::Load, StoreAction::Store)  // only the nearest surface passes
        .record([&](GraphPassRecorder& r) {
          r.draw_renderers(culling, {{lit::kForwardLit}, SortingCriteria::CommonOpaque}, {RenderQueueRange::opaque()});
        });
    graph.add_pass("transparents")
        .write_color(color, LoadAction::Load, StoreAction::Store)
        .read_depth(depth, LoadAction::Load, StoreAction::DontCare)  // tested, not written
        .record([&](GraphPassRecorder& r) {
          r.draw_renderers(culling, {{lit::kForwardLit}, SortingCriteria::CommonTransparent},
                           {RenderQueueRange::transparent()});
        });
    // Nothing reads `sky`: --render-graph cull or merge removes this pass and its bytes.
    graph.add_pass("sky for nobody")
        .write_color(sky, LoadAction::Clear, StoreAction::Store)
        .record([&](GraphPassRecorder& r) { r.draw_skybox(kit.matrices()); });

    return kit.submit(graph, color);  // marks color as the output, executes, submits
  }
};

const PipelineRegistration kGraphExample("graph-example", [] { return std::make_unique<GraphExamplePipeline>(); });

}  // namespace
}  // namespace ontile
