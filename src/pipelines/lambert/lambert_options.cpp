// Parsing and checking of the lambert pipeline's options (see lambert_options.h).
#include "pipelines/lambert/lambert_options.h"

#include <string>

#include "util/error.h"

namespace ontile {
namespace {

[[noreturn]] void bad_value(const std::string& key, const std::string& value, const std::string& valid) {
  throw Error("lambert: " + key + "=" + value + " (valid: " + valid + ")");
}

}  // namespace

const char* lambert_depth_name(PixelFormat depth_format) {
  switch (depth_format) {
    case PixelFormat::D16_UNORM: return "d16";
    case PixelFormat::D24S8: return "d24";
    default: return "d32f";
  }
}

const char* texture_filtering_name(TextureFiltering filtering) {
  switch (filtering) {
    case TextureFiltering::Gltf: return "gltf";
    case TextureFiltering::Bilinear: return "bilinear";
    case TextureFiltering::Trilinear: return "trilinear";
  }
  return "?";
}

LambertOptions parse_lambert_options(const PipelineOptions& options) {
  LambertOptions o;
  const std::string msaa = options.take("msaa", "1");
  if (msaa == "1" || msaa == "2" || msaa == "4" || msaa == "8") {
    o.msaa_samples = std::stoi(msaa);
  } else {
    bad_value("msaa", msaa, "1, 2, 4, 8");
  }
  const std::string depth = options.take("depth", "d32f");
  bool depth_known = false;
  for (PixelFormat f : {PixelFormat::D16_UNORM, PixelFormat::D24S8, PixelFormat::D32_FLOAT}) {
    if (depth == lambert_depth_name(f)) {
      o.depth_format = f;
      depth_known = true;
    }
  }
  if (!depth_known) bad_value("depth", depth, "d16, d24, d32f");
  const std::string reversed = options.take("reversed_z", "off");
  if (reversed != "on" && reversed != "off") bad_value("reversed_z", reversed, "on, off");
  o.reversed_z = reversed == "on";
  const std::string normals = options.take("normals", "none");
  if (normals != "none") {
    o.normals = parse_normal_storage(normals);
    if (!o.normals) bad_value("normals", normals, "none, rgb10a2, rgba16f, oct-rg16");
  }
  const std::string filter = options.take("filter", "gltf");
  bool filter_known = false;
  for (TextureFiltering f : {TextureFiltering::Gltf, TextureFiltering::Bilinear, TextureFiltering::Trilinear}) {
    if (filter == texture_filtering_name(f)) {
      o.filtering = f;
      filter_known = true;
    }
  }
  if (!filter_known) bad_value("filter", filter, "gltf, bilinear, trilinear");
  const std::string color_load = options.take("color_load", "clear");
  if (color_load == "clear") {
    o.color_load = LoadAction::Clear;
  } else if (color_load == "load") {
    o.color_load = LoadAction::Load;
  } else if (color_load == "dont_care") {
    o.color_load = LoadAction::DontCare;
  } else {
    bad_value("color_load", color_load, "clear, load, dont_care");
  }
  const std::string depth_store = options.take("depth_store", "dont_care");
  if (depth_store == "dont_care") {
    o.depth_store = StoreAction::DontCare;
  } else if (depth_store == "store") {
    o.depth_store = StoreAction::Store;
  } else {
    bad_value("depth_store", depth_store, "dont_care, store");
  }
  check_lambert_options(o);
  return o;
}

void check_lambert_options(const LambertOptions& o) {
  if (o.msaa_samples != 1 && o.msaa_samples != 2 && o.msaa_samples != 4 && o.msaa_samples != 8) {
    throw Error("lambert: " + std::to_string(o.msaa_samples) + " samples (valid: 1, 2, 4, 8)");
  }
  if (o.depth_format != PixelFormat::D16_UNORM && o.depth_format != PixelFormat::D24S8 &&
      o.depth_format != PixelFormat::D32_FLOAT) {
    throw Error(std::string("lambert: depth format ") + format_name(o.depth_format) +
                " (valid: d16, d24s8, d32f)");
  }
  if (o.msaa_samples > 1 && (o.normals || o.primitive_id_output)) {
    throw Error("lambert: msaa=" + std::to_string(o.msaa_samples) +
                " with a normal or primitive-id buffer (they are single-sample; use msaa=1)");
  }
  if (o.msaa_samples > 1 && o.color_load == LoadAction::Load) {
    throw Error("lambert: color_load=load with msaa=" + std::to_string(o.msaa_samples) +
                " (multisampled colour lives only in tile memory; use msaa=1)");
  }
}

}  // namespace ontile
