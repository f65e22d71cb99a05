// Render-graph declaration, recording and execution (see render_graph.h; compilation in
// render_graph_compiler.cpp).
#include "context/render_graph.h"

#include <algorithm>

#include "util/error.h"

namespace ontile {
namespace {

const char* load_name(LoadAction a) {
  switch (a) {
    case LoadAction::Load: return "load";
    case LoadAction::Clear: return "clear";
    case LoadAction::DontCare: return "dont-care";
  }
  return "?";
}

const char* store_name(StoreAction a) {
  switch (a) {
    case StoreAction::Store: return "store";
    case StoreAction::DontCare: return "dont-care";
    case StoreAction::Resolve: return "resolve";
    case StoreAction::StoreAndResolve: return "store-and-resolve";
  }
  return "?";
}

}  // namespace

GraphReport graph_report(const GraphDecl& graph, const CompiledGraph& compiled) {
  GraphReport report;
  report.mode = render_graph_mode_name(compiled.mode);
  auto names = [&](const std::vector<int>& resources) {
    std::vector<std::string> out;
    for (int r : resources) out.push_back(graph.resources[r].name);
    return out;
  };
  for (size_t i = 0; i < graph.passes.size(); ++i) {
    const GraphPassDecl& p = graph.passes[i];
    GraphReport::WrittenPass w{p.name, {}, names(p.own_pixel_reads), names(p.texture_reads), compiled.pass_culled[i]};
    for (const GraphWrite& c : p.colors) w.writes.push_back(graph.resources[c.resource].name);
    if (p.depth && !p.depth_read_only) w.writes.push_back(graph.resources[p.depth->resource].name);
    report.passes.push_back(std::move(w));
  }
  for (const NativePass& n : compiled.native_passes) {
    GraphReport::ExecutedPass e;
    e.name = n.name;
    e.external = n.external;
    for (const NativeSubpass& s : n.subpasses) e.subpasses.push_back(graph.passes[s.pass].name);
    for (const NativeAttachment& a : n.attachments) {
      e.attachments.push_back({graph.resources[a.resource].name, load_name(a.load), store_name(a.store), a.memoryless});
    }
    report.native_passes.push_back(std::move(e));
  }
  report.decisions = compiled.decisions;
  return report;
}

bool GraphPassRecorder::on_tile(GraphResource r) const {
  return std::find(inputs_on_tile_.begin(), inputs_on_tile_.end(), r.index) != inputs_on_tile_.end();
}

TextureBinding GraphPassRecorder::texture(GraphResource r, const SamplerDesc& sampler) const {
  if (r.index < 0 || r.index >= static_cast<int>(surfaces_.size()) || !surfaces_[r.index]) {
    throw Error("render graph: resource " + std::to_string(r.index) +
                " is not in memory (declare it with read_texture or read_own_pixel)");
  }
  return {nullptr, RenderTargetRef::of(surfaces_[r.index]), sampler};
}

void GraphPassRecorder::draw_renderers(const CullingResults& culling, const DrawingSettings& drawing,
                                       const FilteringSettings& filtering) {
  commands_.push_back(op::DrawRenderers{culling, drawing, filtering});
}

void GraphPassRecorder::draw_skybox(const CameraMatrices& camera) { commands_.push_back(op::DrawSkybox{camera}); }

void GraphPassRecorder::draw(const DrawCall& draw) { commands_.push_back(op::RawDraw{draw}); }

void GraphPassRecorder::blit_from(GraphResource source, const RenderMaterial* material,
                                  const std::string& pass_name) {
  if (!material) throw Error("blit_from: no material (pass '" + pass_name + "')");
  commands_.push_back(op::DrawFullScreen{material, pass_name, texture(source).render_target});
}

GraphPassBuilder& GraphPassBuilder::write_color(GraphResource r, LoadAction load, StoreAction store) {
  graph_.decl_.passes[pass_].colors.push_back({r.index, load, store});
  return *this;
}

GraphPassBuilder& GraphPassBuilder::write_depth(GraphResource r, LoadAction load, StoreAction store) {
  GraphPassDecl& p = graph_.decl_.passes[pass_];
  if (p.depth) throw Error("render graph: pass '" + p.name + "' has two depth attachments");
  p.depth = GraphWrite{r.index, load, store};
  p.depth_read_only = false;
  return *this;
}

GraphPassBuilder& GraphPassBuilder::read_depth(GraphResource r, LoadAction load, StoreAction store) {
  write_depth(r, load, store);
  graph_.decl_.passes[pass_].depth_read_only = true;
  return *this;
}

GraphPassBuilder& GraphPassBuilder::read_own_pixel(GraphResource r) {
  graph_.decl_.passes[pass_].own_pixel_reads.push_back(r.index);
  return *this;
}

GraphPassBuilder& GraphPassBuilder::read_texture(GraphResource r) {
  graph_.decl_.passes[pass_].texture_reads.push_back(r.index);
  return *this;
}

GraphPassBuilder& GraphPassBuilder::record(std::function<void(GraphPassRecorder&)> record) {
  graph_.records_[pass_] = std::move(record);
  return *this;
}

GraphResource RenderGraph::create(const GraphResourceDesc& desc) {
  decl_.resources.push_back(desc);
  return {static_cast<int>(decl_.resources.size()) - 1};
}

GraphPassBuilder RenderGraph::add_pass(const std::string& name) {
  GraphPassDecl p;
  p.name = name;
  decl_.passes.push_back(std::move(p));
  records_.emplace_back();
  external_records_.emplace_back();
  return GraphPassBuilder(*this, static_cast<int>(decl_.passes.size()) - 1);
}

GraphPassBuilder RenderGraph::add_external_pass(const std::string& name, std::function<void(RenderContext&)> record) {
  GraphPassBuilder builder = add_pass(name);
  decl_.passes.back().external = true;
  external_records_.back() = std::move(record);
  return builder;
}

void RenderGraph::mark_output(GraphResource r) { decl_.outputs.push_back(r.index); }

Surface* RenderGraph::surface(GraphResource r) const {
  if (r.index < 0 || r.index >= static_cast<int>(surfaces_.size())) return nullptr;
  return surfaces_[r.index];
}

void RenderGraph::execute(RenderContext& context) {
  compiled_ = compile_render_graph(decl_, context.config().render_graph, context.config().tiler);
  surfaces_.assign(decl_.resources.size(), nullptr);
  for (size_t r = 0; r < decl_.resources.size(); ++r) {
    if (!compiled_.resource_backed[r]) continue;
    const GraphResourceDesc& d = decl_.resources[r];
    surfaces_[r] = context.create_surface(d.surface_name.empty() ? d.name : d.surface_name, d.format, d.width_px,
                                          d.height_px, d.samples);
  }
  for (const NativePass& native : compiled_.native_passes) {
    if (native.external) {
      if (external_records_[native.subpasses[0].pass]) external_records_[native.subpasses[0].pass](context);
      continue;
    }
    std::vector<AttachmentDesc> attachments;
    for (const NativeAttachment& a : native.attachments) {
      const GraphResourceDesc& d = decl_.resources[a.resource];
      attachments.push_back({d.name, d.format, a.load, a.store, d.clear_value,
                             a.memoryless ? nullptr : surfaces_[a.resource], nullptr});
    }
    context.begin_render_pass(native.name, native.width_px, native.height_px, native.samples,
                              std::move(attachments), native.depth_index);
    for (const NativeSubpass& sub : native.subpasses) {
      context.begin_subpass(sub.color_outputs, sub.inputs, sub.depth_read_only);
      GraphPassRecorder recorder(surfaces_, sub.inputs_on_tile);
      if (records_[sub.pass]) records_[sub.pass](recorder);
      context.execute_command_buffer(recorder);
      context.end_subpass();
    }
    context.end_render_pass();
  }
  if (compiled_.mode != RenderGraphMode::Off) context.add_graph_report(graph_report(decl_, compiled_));
}

}  // namespace ontile
