// Render-graph compilation (see render_graph_compiler.h): liveness from the outputs backwards
// (Filament's FrameGraph culling), native passes grown pass by pass while the Vulkan subpass
// rules hold (Unity's NativePassCompiler), then load/store actions per native attachment.
#include "context/render_graph_compiler.h"

#include <algorithm>

#include "util/error.h"

namespace ontile {
namespace {

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

// Resources a pass writes (a read-only depth attachment is not written).
std::vector<int> writes_of(const GraphPassDecl& p) {
  std::vector<int> out;
  for (const GraphWrite& w : p.colors) out.push_back(w.resource);
  if (p.depth && !p.depth_read_only) out.push_back(p.depth->resource);
  return out;
}

// Resources whose earlier contents a pass needs: sampled, read at its own pixel, or loaded.
std::vector<int> reads_of(const GraphPassDecl& p) {
  std::vector<int> out = p.own_pixel_reads;
  out.insert(out.end(), p.texture_reads.begin(), p.texture_reads.end());
  for (const GraphWrite& w : p.colors) {
    if (w.load == LoadAction::Load) out.push_back(w.resource);
  }
  if (p.depth && (p.depth->load == LoadAction::Load || p.depth_read_only)) out.push_back(p.depth->resource);
  return out;
}

std::vector<GraphWrite> attachments_of(const GraphPassDecl& p) {
  std::vector<GraphWrite> out = p.colors;
  if (p.depth) out.push_back(*p.depth);
  return out;
}

void validate(const GraphDecl& g) {
  const int n = static_cast<int>(g.resources.size());
  auto check = [&](int r, const std::string& where) {
    if (r < 0 || r >= n) throw Error("render graph: " + where + " names resource " + std::to_string(r) + " of " + std::to_string(n));
  };
  for (const GraphResourceDesc& r : g.resources) {
    if (r.width_px <= 0 || r.height_px <= 0 || r.samples < 1) {
      throw Error("render graph: resource '" + r.name + "' has no size (" + std::to_string(r.width_px) + "x" +
                  std::to_string(r.height_px) + ", " + std::to_string(r.samples) + " samples)");
    }
  }
  for (const GraphPassDecl& p : g.passes) {
    const std::vector<GraphWrite> attachments = attachments_of(p);
    for (int r : p.own_pixel_reads) check(r, "pass '" + p.name + "' own-pixel read");
    for (int r : p.texture_reads) check(r, "pass '" + p.name + "' texture read");
    if (p.external) {
      for (const GraphWrite& w : attachments) check(w.resource, "external pass '" + p.name + "'");
      continue;
    }
    if (attachments.empty()) throw Error("render graph: pass '" + p.name + "' renders to no attachment");
    std::vector<int> seen;
    for (const GraphWrite& w : attachments) {
      check(w.resource, "pass '" + p.name + "'");
      if (contains(seen, w.resource)) throw Error("render graph: pass '" + p.name + "' attaches '" + g.resources[w.resource].name + "' twice");
      seen.push_back(w.resource);
      if (w.store == StoreAction::Resolve || w.store == StoreAction::StoreAndResolve) {
        throw Error("render graph: pass '" + p.name + "' resolves '" + g.resources[w.resource].name + "' (not supported in graph passes)");
      }
      const GraphResourceDesc& a = g.resources[w.resource];
      const GraphResourceDesc& first = g.resources[attachments[0].resource];
      if (a.width_px != first.width_px || a.height_px != first.height_px || a.samples != first.samples) {
        throw Error("render graph: pass '" + p.name + "' mixes attachment sizes or sample counts");
      }
    }
  }
  for (int r : g.outputs) check(r, "output");
  // A memoryless resource has no memory to load from, store to or sample.
  auto memoryless_use = [&](int r, const std::string& how) {
    if (g.resources[r].memoryless) throw Error("render graph: memoryless resource '" + g.resources[r].name + "' " + how);
  };
  for (const GraphPassDecl& p : g.passes) {
    for (const GraphWrite& w : attachments_of(p)) {
      if (w.load == LoadAction::Load) memoryless_use(w.resource, "is loaded by pass '" + p.name + "'");
      if (w.store != StoreAction::DontCare) memoryless_use(w.resource, "is stored by pass '" + p.name + "'");
    }
    for (int r : p.texture_reads) memoryless_use(r, "is sampled by pass '" + p.name + "'");
    if (p.external) {
      for (const GraphWrite& w : attachments_of(p)) memoryless_use(w.resource, "is used by external pass '" + p.name + "'");
    }
  }
  for (int r : g.outputs) memoryless_use(r, "is an output");
}

// The native pass being grown, with what the merge rules need to know about it.
struct NativeBuilder {
  std::vector<int> passes;
  std::vector<int> attached;  // resources, in order of first use
  std::vector<int> written;   // resources some subpass wrote
  std::vector<int> sampled;   // resources some subpass reads from memory
  int depth = -1;
  bool external = false;
};

std::optional<GraphReason> merge_blocker(const GraphDecl& g, const NativeBuilder& n, const GraphPassDecl& p,
                                         const TilerConfig& tiler) {
  if (p.external || n.external) return GraphReason::ExternalPass;
  const GraphResourceDesc& mine = g.resources[attachments_of(p)[0].resource];
  const GraphResourceDesc& theirs = g.resources[n.attached[0]];
  if (mine.width_px != theirs.width_px || mine.height_px != theirs.height_px) return GraphReason::SizeDiffers;
  if (mine.samples != theirs.samples) return GraphReason::SampleCountDiffers;
  for (int r : p.texture_reads) {
    if (contains(n.written, r)) return GraphReason::TextureReadOfOutput;
  }
  for (int r : writes_of(p)) {
    if (contains(n.sampled, r)) return GraphReason::WritesSampledTexture;
  }
  if (p.depth && n.depth >= 0 && p.depth->resource != n.depth) return GraphReason::DepthDiffers;
  // A load action applies where a render pass begins: a later subpass cannot clear.
  for (const GraphWrite& w : attachments_of(p)) {
    if (w.load == LoadAction::Clear && contains(n.attached, w.resource)) return GraphReason::ClearsHeldAttachment;
  }
  // The tiler shrinks tiles until the colour attachments fit; merged, they must still fit
  // the smallest tile it will pick (render_pass_executor.h: select_tile_size).
  std::vector<int> colors;
  for (int r : n.attached) {
    if (r != n.depth) colors.push_back(r);
  }
  for (const GraphWrite& w : p.colors) {
    if (!contains(colors, w.resource)) colors.push_back(w.resource);
  }
  int bits = 0;
  for (int r : colors) bits += bits_per_pixel(g.resources[r].format) * g.resources[r].samples;
  int tile_w = 0, tile_h = 0;
  select_tile_size(tiler, bits, tile_w, tile_h);
  const int64_t budget_bits = int64_t{tiler.color_budget_bits_per_px} * tiler.tile_size_px * tiler.tile_size_px;
  if (int64_t{bits} * tile_w * tile_h > budget_bits) return GraphReason::TileBudgetExceeded;
  return std::nullopt;
}

void add_to_native(NativeBuilder& n, const GraphPassDecl& p, int pass_index) {
  n.passes.push_back(pass_index);
  if (p.external) {
    n.external = true;
    return;
  }
  for (int r : p.own_pixel_reads) {
    if (!contains(n.attached, r)) n.sampled.push_back(r);  // not on tile: read from memory
  }
  for (int r : p.texture_reads) n.sampled.push_back(r);
  for (const GraphWrite& w : attachments_of(p)) {
    if (!contains(n.attached, w.resource)) n.attached.push_back(w.resource);
  }
  for (int r : writes_of(p)) {
    if (!contains(n.written, r)) n.written.push_back(r);
  }
  if (p.depth) n.depth = p.depth->resource;
}

bool read_by_later_pass(const GraphDecl& g, const std::vector<bool>& culled, int after_pass, int resource) {
  for (size_t i = after_pass + 1; i < g.passes.size(); ++i) {
    if (!culled[i] && contains(reads_of(g.passes[i]), resource)) return true;
  }
  return false;
}

int attachment_index(const NativePass& native, int resource) {
  for (size_t a = 0; a < native.attachments.size(); ++a) {
    if (native.attachments[a].resource == resource) return static_cast<int>(a);
  }
  return -1;
}

}  // namespace

const char* render_graph_mode_name(RenderGraphMode mode) {
  switch (mode) {
    case RenderGraphMode::Off: return "off";
    case RenderGraphMode::Cull: return "cull";
    case RenderGraphMode::Merge: return "merge";
  }
  return "?";
}

RenderGraphMode parse_render_graph_mode(const std::string& name) {
  if (name == "off") return RenderGraphMode::Off;
  if (name == "cull") return RenderGraphMode::Cull;
  if (name == "merge") return RenderGraphMode::Merge;
  throw Error("render graph mode '" + name + "': expected off, cull or merge");
}

namespace {

// Backwards from the outputs (Filament's culling): which values are still read after each
// pass; passes nothing needs are culled.
std::vector<std::vector<bool>> cull_and_find_live_values(const GraphDecl& g, RenderGraphMode mode, CompiledGraph& out) {
  std::vector<std::vector<bool>> needed_after(g.passes.size());
  std::vector<bool> needed(g.resources.size(), false);
  for (int r : g.outputs) needed[r] = true;
  for (size_t i = g.passes.size(); i-- > 0;) {
    const GraphPassDecl& p = g.passes[i];
    needed_after[i] = needed;
    const std::vector<int> writes = writes_of(p);
    const bool live = mode == RenderGraphMode::Off || p.external ||
                      std::any_of(writes.begin(), writes.end(), [&](int r) { return needed[r]; });
    if (!live) {
      out.pass_culled[i] = true;
      out.decisions.push_back({p.name, {}, GraphReason::CulledUnread});
      continue;
    }
    for (const GraphWrite& w : attachments_of(p)) {
      if (w.load != LoadAction::Load && contains(writes, w.resource)) needed[w.resource] = false;
    }
    for (int r : reads_of(p)) needed[r] = true;
  }
  return needed_after;
}

// One native pass per live pass, or (merge) grown while the merge rules hold.
std::vector<NativeBuilder> group_passes(const GraphDecl& g, RenderGraphMode mode, const TilerConfig& tiler,
                                        CompiledGraph& out) {
  std::vector<NativeBuilder> builders;
  for (size_t i = 0; i < g.passes.size(); ++i) {
    if (out.pass_culled[i]) continue;
    const GraphPassDecl& p = g.passes[i];
    if (mode == RenderGraphMode::Merge && !builders.empty()) {
      const std::optional<GraphReason> blocker = merge_blocker(g, builders.back(), p, tiler);
      out.decisions.push_back({p.name, {}, blocker.value_or(GraphReason::Merged)});
      if (!blocker) {
        add_to_native(builders.back(), p, static_cast<int>(i));
        continue;
      }
    }
    builders.emplace_back();
    add_to_native(builders.back(), p, static_cast<int>(i));
  }
  return builders;
}

NativePass external_pass(const GraphDecl& g, const NativeBuilder& b, std::vector<bool>& written_before,
                         CompiledGraph& out) {
  // What it declares must be in memory; anything it writes counts as written before.
  const GraphPassDecl& p = g.passes[b.passes[0]];
  NativePass native;
  native.name = p.name;
  native.external = true;
  native.subpasses.push_back({b.passes[0], {}, {}, {}, false});
  for (int r : reads_of(p)) out.resource_backed[r] = true;
  for (const GraphWrite& w : attachments_of(p)) out.resource_backed[w.resource] = written_before[w.resource] = true;
  return native;
}

// Attachments in order of first use with their load actions, and each subpass's outputs and
// input attachments.
NativePass subpasses_and_loads(const GraphDecl& g, RenderGraphMode mode, const NativeBuilder& b,
                               const std::vector<bool>& written_before, CompiledGraph& out) {
  NativePass native;
  const GraphResourceDesc& size = g.resources[b.attached[0]];
  native.width_px = size.width_px;
  native.height_px = size.height_px;
  native.samples = size.samples;
  for (int pass_index : b.passes) {
    const GraphPassDecl& p = g.passes[pass_index];
    native.name += (native.name.empty() ? "" : " + ") + p.name;
    NativeSubpass sub;
    sub.pass = pass_index;
    for (int r : p.own_pixel_reads) {
      const int a = attachment_index(native, r);
      if (a >= 0) {
        sub.inputs.push_back(a);
        sub.inputs_on_tile.push_back(r);
        continue;
      }
      if (g.resources[r].memoryless) {
        throw Error("render graph: pass '" + p.name + "' reads memoryless '" + g.resources[r].name +
                    "' outside the render pass that holds it");
      }
      out.resource_backed[r] = true;
    }
    for (int r : p.texture_reads) out.resource_backed[r] = true;
    for (const GraphWrite& w : attachments_of(p)) {
      int a = attachment_index(native, w.resource);
      if (a < 0) {
        a = static_cast<int>(native.attachments.size());
        NativeAttachment att{w.resource, w.load, w.store, false};
        if (mode == RenderGraphMode::Merge) {
          GraphReason load_reason = GraphReason::LoadKept;
          if (!written_before[w.resource]) {
            att.load = w.load == LoadAction::DontCare ? LoadAction::DontCare : LoadAction::Clear;
            load_reason = att.load == LoadAction::Clear ? GraphReason::LoadCleared : GraphReason::LoadDontCare;
          }
          out.decisions.push_back({p.name, g.resources[w.resource].name, load_reason});
        }
        native.attachments.push_back(att);
      }
      if (p.depth && w.resource == p.depth->resource) native.depth_index = a;
    }
    for (const GraphWrite& w : p.colors) sub.color_outputs.push_back(attachment_index(native, w.resource));
    native.subpasses.push_back(sub);
  }
  // Subpasses that leave depth alone keep it read-only (one depth per render pass here, so
  // the others see it but may not write it).
  for (NativeSubpass& sub : native.subpasses) {
    const GraphPassDecl& p = g.passes[sub.pass];
    sub.depth_read_only = native.depth_index >= 0 && (!p.depth || p.depth_read_only);
  }
  return native;
}

// Store actions from what later passes or the outputs still read, and which attachments stay
// out of memory.
void stores_and_memory(const GraphDecl& g, RenderGraphMode mode, const NativeBuilder& b, const std::vector<bool>& later,
                       NativePass& native, CompiledGraph& out) {
  const std::string& last_name = g.passes[b.passes.back()].name;
  for (NativeAttachment& a : native.attachments) {
    const std::string& resource_name = g.resources[a.resource].name;
    bool dropped = false;
    if (mode == RenderGraphMode::Cull && !later[a.resource] && a.store == StoreAction::Store) {
      a.store = StoreAction::DontCare;
      dropped = true;
      out.decisions.push_back({last_name, resource_name, GraphReason::CulledUnreadAttachment});
    } else if (mode == RenderGraphMode::Merge) {
      a.store = later[a.resource] ? StoreAction::Store : StoreAction::DontCare;
      GraphReason reason = GraphReason::TransientNotReadLater;
      if (later[a.resource]) {
        reason = read_by_later_pass(g, out.pass_culled, b.passes.back(), a.resource) ? GraphReason::StoredReadLater
                                                                                     : GraphReason::StoredOutput;
      }
      out.decisions.push_back({last_name, resource_name, reason});
    }
    // As written, only what the author declared memoryless is; merge (and cull, for the
    // stores it drops) leaves out of memory whatever is neither loaded nor stored.
    const bool unused_in_memory = a.load != LoadAction::Load && a.store == StoreAction::DontCare;
    a.memoryless = g.resources[a.resource].memoryless || (unused_in_memory && (mode == RenderGraphMode::Merge || dropped));
    if (!a.memoryless) out.resource_backed[a.resource] = true;
  }
}

}  // namespace

CompiledGraph compile_render_graph(const GraphDecl& g, RenderGraphMode mode, const TilerConfig& tiler) {
  validate(g);
  CompiledGraph out;
  out.mode = mode;
  out.pass_culled.assign(g.passes.size(), false);
  out.resource_backed.assign(g.resources.size(), false);
  const std::vector<std::vector<bool>> needed_after = cull_and_find_live_values(g, mode, out);
  std::vector<bool> written_before(g.resources.size(), false);
  for (const NativeBuilder& b : group_passes(g, mode, tiler, out)) {
    if (b.external) {
      out.native_passes.push_back(external_pass(g, b, written_before, out));
      continue;
    }
    NativePass native = subpasses_and_loads(g, mode, b, written_before, out);
    stores_and_memory(g, mode, b, needed_after[b.passes.back()], native, out);
    for (int r : b.written) written_before[r] = true;
    out.native_passes.push_back(std::move(native));
  }
  for (int r : g.outputs) out.resource_backed[r] = true;
  // Decisions in pass order, each pass's own decision before its attachments'.
  auto order = [&](const GraphDecision& d) {
    size_t pass = 0;
    while (pass < g.passes.size() && g.passes[pass].name != d.pass) ++pass;
    return std::pair(pass, !d.resource.empty());
  };
  std::stable_sort(out.decisions.begin(), out.decisions.end(),
                   [&](const GraphDecision& a, const GraphDecision& b) { return order(a) < order(b); });
  return out;
}

}  // namespace ontile
