// Named builders for a render pass's attachments, instead of positional AttachmentDesc fields:
// `Attachment::stored("color", surface).clear(sky)` reads as the Vulkan attachment description
// it becomes (VkAttachmentDescription: where it lives, loadOp, storeOp, resolve target).
#pragma once
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "tiler/render_pass.h"

namespace ontile {

class Attachment {
 public:
  // Backed by `surface` (its format) and written back at the end of the pass unless told
  // otherwise; what tile memory holds at the start is undefined until clear() or load().
  static Attachment stored(std::string name, Surface* surface) {
    return Attachment(AttachmentDesc{std::move(name), surface->format(), LoadAction::DontCare, StoreAction::Store,
                                     glm::vec4(0.0f), surface, nullptr});
  }
  // Lives only in tile memory (memoryless, VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT): neither
  // loaded nor stored, so it never costs a byte of external traffic.
  static Attachment transient(std::string name, PixelFormat format) {
    return Attachment(AttachmentDesc{std::move(name), format, LoadAction::DontCare, StoreAction::DontCare,
                                     glm::vec4(0.0f), nullptr, nullptr});
  }

  // LoadAction::Clear to `value` (a depth attachment clears to value.x).
  Attachment clear(glm::vec4 value) const { return with([&](AttachmentDesc& d) { d.load = LoadAction::Clear; d.clear_value = value; }); }
  Attachment clear_depth(float depth) const { return clear(glm::vec4(depth)); }
  // LoadAction::Load: the pass starts from what external memory holds.
  Attachment load() const { return with([](AttachmentDesc& d) { d.load = LoadAction::Load; }); }
  // StoreAction::Store / DontCare: keep or drop the pass's result.
  Attachment store() const { return with([](AttachmentDesc& d) { d.store = StoreAction::Store; }); }
  Attachment discard() const { return with([](AttachmentDesc& d) { d.store = StoreAction::DontCare; }); }
  // Backs the attachment by `surface` (null keeps it memoryless) without storing anything: the
  // memory a driver allocates when it cannot make the attachment transient.
  Attachment backed_by(Surface* surface) const { return with([&](AttachmentDesc& d) { d.surface = surface; }); }
  // Multisampled attachment averaged on tile into the single-sample `target` (Vulkan's
  // pResolveAttachments); resolve_into drops the samples, store_and_resolve_into keeps them.
  Attachment resolve_into(Surface* target) const {
    return with([&](AttachmentDesc& d) { d.store = StoreAction::Resolve; d.resolve_surface = target; });
  }
  Attachment store_and_resolve_into(Surface* target) const {
    return with([&](AttachmentDesc& d) { d.store = StoreAction::StoreAndResolve; d.resolve_surface = target; });
  }

  const AttachmentDesc& desc() const { return desc_; }
  operator AttachmentDesc() const { return desc_; }  // NOLINT: builders stand where descs go

 private:
  explicit Attachment(AttachmentDesc desc) : desc_(std::move(desc)) {}
  template <class Edit>
  Attachment with(Edit edit) const {
    Attachment copy = *this;
    edit(copy.desc_);
    return copy;
  }
  AttachmentDesc desc_;
};

}  // namespace ontile
