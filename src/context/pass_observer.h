// A hook into frame execution for tools that show what each render pass did (the HTML report,
// --dump-attachments): called after every render pass has run, while its surfaces still hold
// what the pass left in them. Off unless a ContextConfig names an observer.
#pragma once
#include <cstddef>

#include "tiler/pass_report.h"
#include "tiler/render_pass.h"

namespace ontile {

class PassObserver {
 public:
  virtual ~PassObserver() = default;
  // `index` is the pass's position in the frame's FrameReport::passes (0 starts a new frame).
  // `desc` is the pass as it ran: attachments bound to surfaces (external memory) hold their
  // contents after its store; transient attachments (surface null) lived in tile memory only,
  // and are shown in desc.capture_surfaces when wants_tile_contents() said so (every attachment
  // then has one, valid during this call). Surfaces may change in later passes: copy what you
  // keep.
  virtual void pass_executed(size_t index, const RenderPassDesc& desc, const PassReport& report) = 0;
  // Whether the executor should copy what every tile held at the end of each pass, transient
  // attachments included, into desc.capture_surfaces (costs a copy per tile; no traffic).
  virtual bool wants_tile_contents() const { return false; }
};

}  // namespace ontile
