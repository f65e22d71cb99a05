// The render-graph compiler: from passes that declare what they write and read to the native
// render passes that run (off: as written; cull: unread passes and attachments removed;
// merge: also subpasses, transient attachments, derived load/store), every decision with a
// reason from a fixed set (docs/render-graph.md).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "context/graph_report.h"
#include "tiler/render_pass.h"
#include "tiler/render_pass_executor.h"

namespace ontile {

enum class RenderGraphMode { Off, Cull, Merge };
const char* render_graph_mode_name(RenderGraphMode mode);
// Throws ontile::Error for anything but "off", "cull" or "merge".
RenderGraphMode parse_render_graph_mode(const std::string& name);

// A graph resource: a render target created by descriptor (the graph backs it with memory
// only when it must).
struct GraphResourceDesc {
  std::string name;
  PixelFormat format = PixelFormat::RGBA8_UNORM;
  int width_px = 0, height_px = 0;
  int samples = 1;
  glm::vec4 clear_value{0.0f};  // depth resources use clear_value.x
  std::string surface_name = {};  // the backing surface's name when it differs (blits name passes by it)
  // Never backed by memory (Vulkan's lazily allocated, Metal's memoryless storage): only for
  // attachments that are neither loaded, stored nor sampled. Merge finds these by itself.
  bool memoryless = false;
};

// An attachment a pass renders to, with the load/store actions its author gave.
struct GraphWrite {
  int resource = -1;
  LoadAction load = LoadAction::Clear;
  StoreAction store = StoreAction::Store;
};

struct GraphPassDecl {
  std::string name;
  std::vector<GraphWrite> colors;   // fragment output k writes colors[k]
  std::optional<GraphWrite> depth;  // depth attachment (tested, written unless read-only)
  bool depth_read_only = false;
  std::vector<int> own_pixel_reads;  // read at the fragment's own pixel (input-attachment compatible)
  std::vector<int> texture_reads;    // sampled anywhere (needs the resource in memory)
  // Records its own render passes, blits or features into the context (Unity's unsafe pass):
  // never culled or merged; what it reads and writes is what it declares.
  bool external = false;
};

struct GraphDecl {
  std::vector<GraphResourceDesc> resources;
  std::vector<GraphPassDecl> passes;
  std::vector<int> outputs;  // the frame's final outputs: read after the graph
};

// One attachment of a native pass with the actions that run.
struct NativeAttachment {
  int resource = -1;
  LoadAction load = LoadAction::Clear;
  StoreAction store = StoreAction::Store;
  bool memoryless = false;  // neither loaded nor stored: never backed by memory in this pass
};

struct NativeSubpass {
  int pass = -1;                        // index into GraphDecl::passes
  std::vector<int> color_outputs;       // attachment indices of the native pass
  std::vector<int> inputs;              // attachment indices read by framebuffer fetch
  std::vector<int> inputs_on_tile;      // resources among own_pixel_reads read as inputs
  bool depth_read_only = false;
};

struct NativePass {
  std::string name;
  bool external = false;  // an external pass: runs its own commands, no attachments here
  int width_px = 0, height_px = 0, samples = 1;
  std::vector<NativeAttachment> attachments;
  int depth_index = -1;
  std::vector<NativeSubpass> subpasses;
};

struct CompiledGraph {
  RenderGraphMode mode = RenderGraphMode::Off;
  std::vector<NativePass> native_passes;
  std::vector<bool> pass_culled;       // per GraphDecl pass
  std::vector<bool> resource_backed;   // per resource: needs a surface in memory
  std::vector<GraphDecision> decisions;
};

// Throws ontile::Error for an invalid graph (a handle out of range, a pass without
// attachments, an output nothing writes). `tiler` supplies the tile-memory budget.
CompiledGraph compile_render_graph(const GraphDecl& graph, RenderGraphMode mode, const TilerConfig& tiler);

// The report's view of a compilation: passes as written, native passes as executed, decisions.
GraphReport graph_report(const GraphDecl& graph, const CompiledGraph& compiled);

}  // namespace ontile
