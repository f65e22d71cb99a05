// Transaction elimination's CRC history (see transaction_elimination.h). The CRC is zlib's
// crc32 (a well-kept library; the hardware's CRC polynomial is not published, and any CRC makes
// the same decisions unless two different tiles collide).
#include "memory/transaction_elimination.h"

#include <zlib.h>

#include <algorithm>

namespace ontile {

namespace {
struct CrcTargetsName {
  CrcTargets targets;
  const char* name;
};
constexpr CrcTargetsName kCrcTargetsNames[] = {{CrcTargets::OnePerPass, "on"},
                                               {CrcTargets::SingleTargetPasses, "single-target-passes"},
                                               {CrcTargets::EveryTarget, "every-target"}};
}  // namespace

const char* crc_targets_name(CrcTargets targets) {
  for (const CrcTargetsName& n : kCrcTargetsNames) {
    if (n.targets == targets) return n.name;
  }
  return nullptr;
}

std::vector<std::string> crc_targets_names() {
  std::vector<std::string> names;
  for (const CrcTargetsName& n : kCrcTargetsNames) names.push_back(n.name);
  return names;
}

const CrcTargets* parse_crc_targets(const std::string& name) {
  for (const CrcTargetsName& n : kCrcTargetsNames) {
    if (name == n.name) return &n.targets;
  }
  return nullptr;
}

bool TileSignatureHistory::valid(const std::string& key) const {
  const auto it = tables_.find(key);
  return it != tables_.end() &&
         std::any_of(it->second.valid.begin(), it->second.valid.end(), [](uint8_t v) { return v != 0; });
}

void TileSignatureHistory::invalidate(const std::string& key) {
  const auto it = tables_.find(key);
  if (it != tables_.end()) std::fill(it->second.valid.begin(), it->second.valid.end(), 0);
}

TileSignatureHistory::Table& TileSignatureHistory::table(const std::string& key, int tiles) {
  Table& t = tables_[key];
  if (t.crc.size() != static_cast<size_t>(tiles)) {
    t.crc.assign(static_cast<size_t>(tiles), 0);
    t.valid.assign(static_cast<size_t>(tiles), 0);
  }
  return t;
}

uint32_t tile_crc(const SurfaceBytes& surface, const TileRect& rect) {
  uLong crc = crc32(0L, Z_NULL, 0);
  const auto row_bytes =
      static_cast<uInt>(static_cast<size_t>(rect.width) * surface.samples * bytes_per_pixel(surface.format));
  for (int y = rect.y0; y < rect.y0 + rect.height; ++y) crc = crc32(crc, surface.pixel(rect.x0, y), row_bytes);
  return static_cast<uint32_t>(crc);
}

bool eliminate_tile_write(TileSignatureHistory::Table& table, int tile, uint32_t crc) {
  const bool same = table.valid[tile] && table.crc[tile] == crc;
  table.crc[tile] = crc;
  table.valid[tile] = 1;
  return same;
}

}  // namespace ontile
