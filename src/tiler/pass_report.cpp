// Sums of pass counters (see pass_report.h).
#include "tiler/pass_report.h"

namespace ontile {

void GeometryCounters::add(const GeometryCounters& o) {
  triangles_submitted += o.triangles_submitted;
  triangles_non_finite += o.triangles_non_finite;
  triangles_culled += o.triangles_culled;
  triangles_zero_area += o.triangles_zero_area;
  triangles_outside += o.triangles_outside;
  triangles_clipped += o.triangles_clipped;
  triangles_binned += o.triangles_binned;
  vertices_shaded += o.vertices_shaded;
  varyings_sanitized += o.varyings_sanitized;
  tile_list_entries += o.tile_list_entries;
  index_bytes_read += o.index_bytes_read;
  vertex_bytes_read += o.vertex_bytes_read;
  parameter_bytes_written += o.parameter_bytes_written;
  parameter_position_bytes_written += o.parameter_position_bytes_written;
  parameter_varying_bytes_written += o.parameter_varying_bytes_written;
}

void TileCounters::add(const TileCounters& o) {
  tiles_executed += o.tiles_executed;
  parameter_bytes_read += o.parameter_bytes_read;
  fragments_shaded += o.fragments_shaded;
  fragments_depth_rejected += o.fragments_depth_rejected;
  samples_written += o.samples_written;
  cells_rasterized += o.cells_rasterized;
  cells_hiz_rejected += o.cells_hiz_rejected;
}

uint64_t PassReport::attachment_bytes_loaded() const {
  uint64_t sum = 0;
  for (const auto& a : attachments) sum += a.bytes_loaded;
  return sum;
}

uint64_t PassReport::attachment_bytes_stored() const {
  uint64_t sum = 0;
  for (const auto& a : attachments) sum += a.bytes_stored + a.bytes_resolved;
  return sum;
}

uint64_t PassReport::bytes_read() const {
  return attachment_bytes_loaded() + tiles.parameter_bytes_read + geometry.index_bytes_read +
         geometry.vertex_bytes_read + texture.bytes_read;
}

uint64_t PassReport::bytes_written() const {
  return attachment_bytes_stored() + geometry.parameter_bytes_written;
}

}  // namespace ontile
