// The settings the accuracy sweep measures: the lambert pipeline's default, then one axis at a
// time varied from it (MSAA, subpixel precision, depth format x reversed Z, normal storage,
// texture filtering).
#pragma once
#include <string>
#include <vector>

#include "pipelines/lambert/lambert_options.h"

namespace ontile {

struct SweepSetting {
  std::string name;   // CSV key, e.g. "default", "msaa=4", "depth=d16 reversed_z=on"
  std::string axis;   // "default", "msaa", "subpixel", "depth", "normals", "filter"
  std::string label;  // short plot label, e.g. "MSAA4", "D16R"
  LambertOptions options;
  int subpixel_bits = 8;  // TilerConfig::subpixel_bits
};

// default; msaa 2, 4, 8; subpixel 4; depth d16, d24 (standard) and d16, d24, d32f (reversed);
// normals rgb10a2, rgba16f, oct-rg16; filter bilinear, trilinear: 15 settings. Values equal
// to the default (msaa 1, subpixel 8, d32f standard, no normal buffer) are the default row.
std::vector<SweepSetting> sweep_settings();
// The axes in plot/legend order.
std::vector<std::string> sweep_axes();

}  // namespace ontile
