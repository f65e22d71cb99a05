// Option parsing of the forward and deferred pipelines (see deferred_options.h).
#include "pipelines/deferred/deferred_options.h"

#include <charconv>

#include "util/error.h"

namespace ontile {
namespace {

int parse_int(const std::string& key, const std::string& text, int min_value, int max_value) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < min_value || value > max_value) {
    throw Error("pipeline option " + key + "='" + text + "': expected an integer in [" + std::to_string(min_value) +
                ", " + std::to_string(max_value) + "]");
  }
  return value;
}

bool parse_switch(const std::string& key, const std::string& text, const char* on, const char* off) {
  if (text == on) return true;
  if (text == off) return false;
  throw Error("pipeline option " + key + "='" + text + "': expected " + on + " or " + off);
}

}  // namespace

DeferredOptions parse_deferred_options(const PipelineOptions& options, DeferredVariant variant) {
  DeferredOptions o;
  o.layout = gbuffer_layout(options.take("gbuffer", "vulkan-samples"));
  o.generated_lights = parse_int("lights", options.take("lights", "0"), 0, 65536);
  const std::string tonemap = options.take("tonemap", "auto");
  if (tonemap == "auto") {
    o.tonemap = o.layout.light_format != PixelFormat::RGBA8_SRGB;
  } else {
    o.tonemap = parse_switch("tonemap", tonemap, "on", "off");
  }
  if (variant == DeferredVariant::Subpass) {
    o.transient = parse_switch("transient", options.take("transient", "on"), "on", "off");
    o.store_gbuffer = parse_switch("gbuffer_store", options.take("gbuffer_store", "dont-care"), "store", "dont-care");
    if (o.store_gbuffer && o.transient) {
      throw Error("pipeline option gbuffer_store=store needs transient=off (a transient attachment has no memory to store to)");
    }
    o.two_render_passes =
        parse_switch("technique", options.take("technique", "subpasses"), "render-passes", "subpasses");
    if (o.two_render_passes && (o.store_gbuffer || !o.transient)) {
      throw Error("pipeline option technique=render-passes stores and loads the G-buffer itself: leave transient and "
                  "gbuffer_store at their defaults");
    }
  }
  if (variant == DeferredVariant::Forward) {
    o.msaa_samples = parse_int("msaa", options.take("msaa", "1"), 1, 8);
    if (o.msaa_samples != 1 && o.msaa_samples != 2 && o.msaa_samples != 4 && o.msaa_samples != 8) {
      throw Error("pipeline option msaa='" + std::to_string(o.msaa_samples) + "': expected 1, 2, 4 or 8");
    }
    o.separate_resolve = !parse_switch("resolve", options.take("resolve", "on-tile"), "on-tile", "separate");
    if (o.separate_resolve && o.msaa_samples == 1) {
      throw Error("pipeline option resolve=separate needs msaa=2, 4 or 8");
    }
  }
  return o;
}

}  // namespace ontile
