// Pass capture (see pass_capture.h).
#include "report/pass_capture.h"

namespace ontile {

const char* load_action_name(LoadAction action) {
  switch (action) {
    case LoadAction::Load: return "load";
    case LoadAction::Clear: return "clear";
    case LoadAction::DontCare: return "dont-care";
  }
  return "?";
}

const char* store_action_name(StoreAction action) {
  switch (action) {
    case StoreAction::Store: return "store";
    case StoreAction::DontCare: return "dont-care";
    case StoreAction::Resolve: return "resolve";
    case StoreAction::StoreAndResolve: return "store+resolve";
  }
  return "?";
}

void PassCapture::pass_executed(size_t index, const RenderPassDesc& desc, const PassReport&) {
  if (index == 0) passes_.clear();
  CapturedPass pass;
  pass.index = index;
  pass.name = desc.name;
  pass.width_px = desc.width_px;
  pass.height_px = desc.height_px;
  pass.samples = desc.samples;
  pass.subpasses = desc.subpasses.size();
  for (size_t i = 0; i < desc.attachments.size(); ++i) {
    const AttachmentDesc& a = desc.attachments[i];
    CapturedAttachment c;
    c.name = a.name;
    c.format = a.format;
    c.load = load_action_name(a.load);
    c.store = store_action_name(a.store);
    c.transient = a.surface == nullptr;
    c.depth = static_cast<int>(i) == desc.depth_index;
    if (copy_contents_ && a.surface) c.contents = std::make_shared<const Surface>(*a.surface);
    // A transient attachment never reaches memory: what its tiles held at the end of the pass.
    const Surface* tile_copy = i < desc.capture_surfaces.size() ? desc.capture_surfaces[i] : nullptr;
    if (copy_contents_ && !a.surface && tile_copy) c.contents = std::make_shared<const Surface>(*tile_copy);
    if (copy_contents_ && a.resolve_surface) c.resolved = std::make_shared<const Surface>(*a.resolve_surface);
    pass.attachments.push_back(std::move(c));
  }
  passes_.push_back(std::move(pass));
}

}  // namespace ontile
