// ontile.render's options dictionary (see render_options.h). The ranges and choices are those
// of the `ontile render` flags (apps/ontile/cmd_render.cpp), so a value the CLI refuses is a
// ValueError here too.
#include "render_options.h"

#include "memory/transaction_elimination.h"
#include "tiler/gpu_presets.h"

#include <algorithm>
#include <map>
#include <vector>

#include "util/error.h"

namespace py = pybind11;

namespace ontile::python {
namespace {

const std::vector<int> kTileSizesPx = {4, 8, 16, 32, 64};
const std::vector<int> kCacheSizesKib = {16, 32, 64, 128, 256, 512, 1024, 2048};

std::string text_of(const py::handle& value) { return py::str(value).cast<std::string>(); }

// "a, b, c" (appended piece by piece: GCC 12's LTO warns on `"" + std::string` here).
std::string joined(const std::vector<std::string>& items) {
  std::string list;
  for (const std::string& item : items) {
    if (!list.empty()) list += ", ";
    list += item;
  }
  return list;
}

int integer(const std::string& key, const py::handle& value) {
  if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value)) {
    throw Error("options['" + key + "']: expected an integer, got " + text_of(py::repr(value)));
  }
  return value.cast<int>();
}

int in_range(const std::string& key, const py::handle& value, int low, int high) {
  const int v = integer(key, value);
  if (v < low || v > high) {
    throw Error("options['" + key + "']: " + std::to_string(v) + " not in " + std::to_string(low) + ".." +
                std::to_string(high));
  }
  return v;
}

int member(const std::string& key, const py::handle& value, const std::vector<int>& allowed) {
  const int v = integer(key, value);
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    std::vector<std::string> names;
    for (int a : allowed) names.push_back(std::to_string(a));
    throw Error("options['" + key + "']: " + std::to_string(v) + " not one of " + joined(names));
  }
  return v;
}

std::string choice(const std::string& key, const py::handle& value, const std::vector<std::string>& allowed) {
  const std::string v = py::isinstance<py::str>(value) ? value.cast<std::string>() : std::string();
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    throw Error("options['" + key + "']: " + text_of(py::repr(value)) + " not one of " + joined(allowed));
  }
  return v;
}

// A --set value as the CLI would receive it: strings as they are, numbers in Python's spelling.
std::string set_value(const std::string& key, const py::handle& value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "on" : "off";
  if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) return text_of(value);
  throw Error("options['set']['" + key + "']: expected a string or a number, got " + text_of(py::repr(value)));
}

}  // namespace

ParsedOptions parse_render_options(const py::dict& options, ParsedOptions parsed) {
  RenderSettings& s = parsed.settings;
  using Handler = void (*)(const std::string&, const py::handle&, ParsedOptions&);
  static const std::map<std::string, Handler> kHandlers = {
      {"tile", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.tiler.tile_size_px = member(k, v, kTileSizesPx); }},
      {"budget", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.tiler.color_budget_bits_per_px = in_range(k, v, 32, 4096); }},
      {"subpixel_bits", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.tiler.subpixel_bits = member(k, v, {4, 8}); }},
      {"arch", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.tiler.architecture = choice(k, v, {"tbdr", "imr"}) == "imr" ? Architecture::Imr
                                                                                          : Architecture::Tbdr; }},
      {"afbc", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.tiler.afbc = py::isinstance<py::bool_>(v) ? v.cast<bool>() : choice(k, v, {"on", "off"}) == "on"; }},
      {"texture_cache_kib", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.tiler.texture_cache.size_bytes = static_cast<uint32_t>(member(k, v, kCacheSizesKib)) * 1024; }},
      {"rt_cache_kib", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.tiler.render_target_cache.size_bytes = static_cast<uint32_t>(member(k, v, kCacheSizesKib)) * 1024; }},
      {"parameter_cache_kib", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.tiler.parameter_cache.size_bytes = static_cast<uint32_t>(in_range(k, v, 0, 65536)) * 1024; }},
      {"render_graph", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.render_graph = parse_render_graph_mode(choice(k, v, {"off", "cull", "merge"})); }},
      {"gbuffer", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.options.set("gbuffer", set_value(k, v)); }},
      {"lights", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.options.set("lights", set_value(k, v)); }},
      {"gpu", [](const std::string&, const py::handle&, ParsedOptions&) {}},  // applied before the others
      {"idvs", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.tiler.idvs = py::isinstance<py::bool_>(v) ? v.cast<bool>() : choice(k, v, {"on", "off"}) == "on"; }},
      {"varying_precision", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         p.settings.context.tiler.varying_precision =
             choice(k, v, {"fp32", "fp16"}) == "fp16" ? VaryingPrecision::Fp16 : VaryingPrecision::Fp32; }},
      {"tiles", [](const std::string& k, const py::handle& v, ParsedOptions& p) {
         if (!py::isinstance<py::bool_>(v)) throw Error("options['" + k + "']: expected True or False");
         p.tile_report = v.cast<bool>(); }},
  };
  if (options.contains("gpu")) {
    parsed.gpu = choice("gpu", options["gpu"], gpu_preset_list());
    apply_gpu_preset(*find_gpu_preset(parsed.gpu), s.context.tiler);
  }
  for (const auto& [key_handle, value] : options) {
    const std::string key = text_of(key_handle);
    if (key == "set") {
      if (!py::isinstance<py::dict>(value)) throw Error("options['set']: expected a dict of pipeline options");
      for (const auto& [k, v] : value.cast<py::dict>()) {
        const std::string name = text_of(k);
        if (name.empty()) throw Error("options['set']: empty option name");
        s.options.set(name, set_value(name, v));
      }
      continue;
    }
    const auto it = kHandlers.find(key);
    if (it == kHandlers.end()) {
      std::vector<std::string> valid = {"set"};
      for (const auto& [name, handler] : kHandlers) valid.push_back(name);
      throw Error("options: unknown key '" + key + "' (valid: " + joined(valid) + ")");
    }
    it->second(key, value, parsed);
  }
  // As the CLI: the preset's transaction elimination compares 16x16 tiles only.
  const TilerConfig& tiler = s.context.tiler;
  if (tiler.transaction_elimination && tiler.tile_size_rule == TileSizeRule::Budget &&
      tiler.tile_size_px != kTransactionEliminationTilePx) {
    throw Error("options['tile']: gpu " + parsed.gpu + " turns on transaction elimination, which needs 16x16 tiles");
  }
  return parsed;
}

}  // namespace ontile::python
