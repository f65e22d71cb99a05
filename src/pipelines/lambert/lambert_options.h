// The lambert pipeline's options (`ontile render --set KEY=VALUE`): MSAA, depth format,
// reversed Z, an optional stored normal buffer, texture filtering, and the colour load and depth
// store actions (Vulkan-Samples render_passes). Defaults reproduce the pipeline's original image
// and traffic bit for bit.
#pragma once
#include <optional>

#include "pipelines/lit/lit_shader.h"
#include "pipelines/kit/pipeline.h"

namespace ontile {

struct LambertOptions {
  int msaa_samples = 1;                                // msaa=1|2|4|8
  PixelFormat depth_format = PixelFormat::D32_FLOAT;   // depth=d16|d24|d32f (d24 = D24S8)
  bool reversed_z = false;                             // reversed_z=on|off
  std::optional<NormalStorage> normals;                // normals=none|rgb10a2|rgba16f|oct-rg16
  TextureFiltering filtering = TextureFiltering::Gltf; // filter=gltf|bilinear|trilinear
  // color_load=clear|load|dont_care: the colour target's load action. `load` reads the target's
  // previous contents (a new target holds zeros); dont_care starts from undefined contents,
  // which ontile defines as the clear value, so its image equals clear's. load needs msaa=1.
  LoadAction color_load = LoadAction::Clear;
  // depth_store=dont_care|store: whether depth is written back (it then has a surface).
  StoreAction depth_store = StoreAction::DontCare;
  // Not a --set option: an extra stored R32F target of primitive ids (for the accuracy sweep).
  bool primitive_id_output = false;
};

// Takes the keys above from `options` (the caller rejects the rest). Throws ontile::Error
// naming the key and the bad value, e.g. "lambert: msaa=3 (valid: 1, 2, 4, 8)".
LambertOptions parse_lambert_options(const PipelineOptions& options);
// Throws Error for combinations the pipeline cannot render: a normal buffer or primitive ids
// with MSAA (they are single-sample targets), a sample count other than 1, 2, 4, 8, or loading
// a multisampled colour target (it lives only in tile memory).
void check_lambert_options(const LambertOptions& options);

// "d16", "d24", "d32f" for the three depth formats.
const char* lambert_depth_name(PixelFormat depth_format);
// "gltf", "bilinear", "trilinear".
const char* texture_filtering_name(TextureFiltering filtering);

}  // namespace ontile
