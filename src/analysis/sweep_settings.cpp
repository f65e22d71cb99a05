// The sweep's settings (see sweep_settings.h).
#include "analysis/sweep_settings.h"

namespace ontile {

std::vector<std::string> sweep_axes() { return {"default", "msaa", "subpixel", "depth", "normals", "filter"}; }

std::vector<SweepSetting> sweep_settings() {
  std::vector<SweepSetting> settings;
  settings.push_back({"default", "default", "DEFAULT", {}, 8});
  for (int samples : {2, 4, 8}) {
    SweepSetting s{"msaa=" + std::to_string(samples), "msaa", "MSAA" + std::to_string(samples), {}, 8};
    s.options.msaa_samples = samples;
    settings.push_back(s);
  }
  settings.push_back({"subpixel_bits=4", "subpixel", "SUB4", {}, 4});
  for (bool reversed : {false, true}) {
    for (PixelFormat f : {PixelFormat::D16_UNORM, PixelFormat::D24S8, PixelFormat::D32_FLOAT}) {
      if (!reversed && f == PixelFormat::D32_FLOAT) continue;  // the default
      const std::string depth = lambert_depth_name(f);
      SweepSetting s{"depth=" + depth + (reversed ? " reversed_z=on" : ""), "depth", depth + (reversed ? "R" : ""), {}, 8};
      for (char& c : s.label) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
      s.options.depth_format = f;
      s.options.reversed_z = reversed;
      settings.push_back(s);
    }
  }
  const char* normal_labels[] = {"N10", "N16F", "NOCT"};
  for (NormalStorage n : all_normal_storages()) {
    SweepSetting s{std::string("normals=") + normal_storage_name(n), "normals",
                   normal_labels[static_cast<int>(n)], {}, 8};
    s.options.normals = n;
    settings.push_back(s);
  }
  for (TextureFiltering f : {TextureFiltering::Bilinear, TextureFiltering::Trilinear}) {
    SweepSetting s{std::string("filter=") + texture_filtering_name(f), "filter",
                   f == TextureFiltering::Bilinear ? "BILIN" : "TRILIN", {}, 8};
    s.options.filtering = f;
    settings.push_back(s);
  }
  return settings;
}

}  // namespace ontile
