// The render-graph API beside the explicit render passes (docs/render-graph.md): resources are
// created by descriptor and named; a pass declares its colour/depth outputs, what it reads at
// its own pixel and what it samples, and records its draws. execute() compiles the graph with
// the context's --render-graph mode (off | cull | merge) and records the native passes.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "context/command_buffer.h"
#include "context/render_context.h"
#include "context/render_graph_compiler.h"

namespace ontile {

struct GraphResource {
  int index = -1;
  bool valid() const { return index >= 0; }
};

// What a pass records its draws into: the command buffer recording calls, the context's
// draw calls, and how to reach the resources it declared reading.
class GraphPassRecorder : public CommandBuffer {
 public:
  GraphPassRecorder(const std::vector<Surface*>& surfaces, std::vector<int> inputs_on_tile)
      : CommandBuffer("graph pass"), surfaces_(surfaces), inputs_on_tile_(std::move(inputs_on_tile)) {}

  // True when an own-pixel read is an input attachment of this subpass (its pass was merged
  // after the writer); otherwise the pass samples the stored resource as a texture.
  bool on_tile(GraphResource r) const;
  // The resource as a texture; only valid for resources the pass declared reading.
  TextureBinding texture(GraphResource r, const SamplerDesc& sampler = {}) const;

  void draw_renderers(const CullingResults& culling, const DrawingSettings& drawing,
                      const FilteringSettings& filtering);
  void draw_skybox(const CameraMatrices& camera);
  void draw(const DrawCall& draw);  // pre-built functors that outlive submit()
  // A full-screen triangle with `source` bound as "_MainTex" (clamped, no mipmaps), as
  // CommandBuffer::blit draws it; the destination is the pass's colour output.
  void blit_from(GraphResource source, const RenderMaterial* material, const std::string& pass_name);

 private:
  const std::vector<Surface*>& surfaces_;
  std::vector<int> inputs_on_tile_;
};

class RenderGraph;

// Declares one pass; returned by RenderGraph::add_pass, calls chain.
class GraphPassBuilder {
 public:
  GraphPassBuilder(RenderGraph& graph, int pass) : graph_(graph), pass_(pass) {}
  // Fragment output k writes the k-th colour written. The load/store actions are the author's:
  // `--render-graph off` runs them as given, merge derives its own.
  GraphPassBuilder& write_color(GraphResource r, LoadAction load, StoreAction store);
  GraphPassBuilder& write_depth(GraphResource r, LoadAction load, StoreAction store);
  // A depth attachment tested but never written (Vulkan's read-only depth).
  GraphPassBuilder& read_depth(GraphResource r, LoadAction load = LoadAction::Load,
                               StoreAction store = StoreAction::DontCare);
  // Read at the fragment's own pixel only (input-attachment compatible).
  GraphPassBuilder& read_own_pixel(GraphResource r);
  // Sampled at any texel (the resource must be in memory).
  GraphPassBuilder& read_texture(GraphResource r);
  GraphPassBuilder& record(std::function<void(GraphPassRecorder&)> record);

 private:
  RenderGraph& graph_;
  int pass_;
};

class RenderGraph {
 public:
  GraphResource create(const GraphResourceDesc& desc);
  GraphPassBuilder add_pass(const std::string& name);
  // A pass that records straight into the context (its own render passes, blits, renderer
  // features: Unity's unsafe pass). Never culled or merged; declare what it reads and writes
  // on the builder so that the compiler keeps those resources in memory.
  GraphPassBuilder add_external_pass(const std::string& name, std::function<void(RenderContext&)> record);
  // A final output of the frame: read after the graph, so always stored.
  void mark_output(GraphResource r);

  // Compiles with context.config().render_graph, creates the surfaces the compiled graph
  // needs in memory, and records its native passes into the context (run by submit()).
  void execute(RenderContext& context);
  // The surface backing `r` after execute(); null for a transient or culled resource.
  Surface* surface(GraphResource r) const;

  const GraphDecl& declaration() const { return decl_; }
  const CompiledGraph& compiled() const { return compiled_; }

 private:
  friend class GraphPassBuilder;
  GraphDecl decl_;
  std::vector<std::function<void(GraphPassRecorder&)>> records_;
  std::vector<std::function<void(RenderContext&)>> external_records_;
  std::vector<Surface*> surfaces_;
  CompiledGraph compiled_;
};

}  // namespace ontile
