// What the render-graph compiler decided and why, in the forms users read a frame report in:
// the JSON report's "graph" section and a table after the traffic table.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ontile {

// The fixed set of reasons (docs/render-graph.md has the table); each implies its decision.
enum class GraphReason {
  Merged,                  // merged: same size and samples, only own-pixel reads of its outputs
  TextureReadOfOutput,     // not merged: samples a texture the native pass writes
  WritesSampledTexture,    // not merged: writes a texture the native pass samples
  SizeDiffers,             // not merged: attachment size differs
  SampleCountDiffers,      // not merged: sample count differs
  DepthDiffers,            // not merged: another depth attachment (one per native pass)
  ClearsHeldAttachment,    // not merged: clears an attachment the native pass already holds
  TileBudgetExceeded,      // not merged: the attachments would not fit tile memory
  ExternalPass,            // not merged: an external pass records its own render passes
  CulledUnread,            // culled: no later pass or output reads what it writes
  CulledUnreadAttachment,  // culled: nothing reads this attachment (store: dont-care)
  StoredReadLater,         // stored: a later render pass reads it
  StoredOutput,            // stored: a final output of the frame
  TransientNotReadLater,   // transient: nothing later reads it (store: dont-care)
  LoadCleared,             // load: cleared (nothing earlier wrote it)
  LoadDontCare,            // load: dont-care (nothing earlier wrote it, no clear asked)
  LoadKept,                // load: an earlier render pass wrote it
};

const char* graph_decision_name(GraphReason reason);  // "merged", "not merged", "culled", ...
const char* graph_reason_name(GraphReason reason);    // "texture read of an earlier output", ...

struct GraphDecision {
  std::string pass;      // the graph pass the decision is about
  std::string resource;  // the attachment, empty for a decision about the pass itself
  GraphReason reason = GraphReason::Merged;
};

struct GraphReport {
  std::string mode;  // "cull" or "merge"
  struct WrittenPass {
    std::string name;
    std::vector<std::string> writes, own_pixel_reads, texture_reads;
    bool culled = false;
  };
  struct ExecutedPass {
    std::string name;
    std::vector<std::string> subpasses;  // graph passes, in order
    bool external = false;
    struct Attachment {
      std::string resource, load, store;
      bool memoryless = false;
    };
    std::vector<Attachment> attachments;
  };
  std::vector<WrittenPass> passes;
  std::vector<ExecutedPass> native_passes;
  std::vector<GraphDecision> decisions;
};

nlohmann::json graph_report_json(const GraphReport& report);
std::string graph_report_table(const GraphReport& report);

}  // namespace ontile
