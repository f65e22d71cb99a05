// The immediate-mode memory model: no tile memory and no parameter buffer; every fragment's
// colour and depth accesses go through the render-target cache (imr_model.h).
#pragma once
#include "memory/memory_model.h"

namespace ontile {

class ImrMemory final : public MemoryModel {
 public:
  explicit ImrMemory(const MemoryConfig& config);
  void begin_pass(const PassMemoryDesc& pass) override { pass_ = pass; traffic_ = ImrTraffic{}; }
  bool records_fragments() const override { return true; }
  void tile_loaded(int, const TileRect&) override {}
  void tile_stored(int, const TileRect&) override {}
  void fragments(const std::vector<TileTrace>& traces) override;
  ParameterBufferWrites parameter_buffer_written(const ParameterBufferWrites&) override { return {}; }
  bool replays_parameter_reads() const override { return false; }
  void parameter_read(uint64_t, uint64_t) override {}
  uint64_t parameter_buffer_read(uint64_t, TextureTraffic& cache) override {
    cache = TextureTraffic{};
    return 0;
  }
  PassAttachmentTraffic end_pass() override;

 private:
  PassMemoryDesc pass_;
  ImrTraffic traffic_;
};

}  // namespace ontile
