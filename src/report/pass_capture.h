// What each render pass of a frame left in its attachments, captured through the context's
// PassObserver hook for the HTML report and --dump-attachments: the pass's attachments with
// their load/store actions and a copy of every attachment after the pass (transient ones from
// the tiles' inspection copies).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "context/pass_observer.h"
#include "tiler/surface.h"

namespace ontile {

struct CapturedAttachment {
  std::string name;
  PixelFormat format = PixelFormat::RGBA8_UNORM;
  std::string load, store;  // "load", "clear", "dont-care"; "store", "dont-care", "resolve", "store+resolve"
  bool transient = false;   // tile memory only: contents are what its tiles held at the pass's end
  bool depth = false;
  std::shared_ptr<const Surface> contents;  // the surface after the pass (transient: the tiles' copy)
  std::shared_ptr<const Surface> resolved;  // the resolve target after the pass, if any
};

struct CapturedPass {
  size_t index = 0;  // position in FrameReport::passes
  std::string name;
  int width_px = 0, height_px = 0, samples = 1;
  size_t subpasses = 0;
  std::vector<CapturedAttachment> attachments;
};

const char* load_action_name(LoadAction action);
const char* store_action_name(StoreAction action);

// Collects every pass of the last frame submitted (a pass with index 0 starts a new frame, so
// with --frames N only the last frame is kept). With copy_contents false only the descriptions
// are kept (no surface copies).
class PassCapture : public PassObserver {
 public:
  explicit PassCapture(bool copy_contents = true) : copy_contents_(copy_contents) {}
  void pass_executed(size_t index, const RenderPassDesc& desc, const PassReport& report) override;
  bool wants_tile_contents() const override { return copy_contents_; }
  const std::vector<CapturedPass>& passes() const { return passes_; }

 private:
  bool copy_contents_;
  std::vector<CapturedPass> passes_;
};

}  // namespace ontile
