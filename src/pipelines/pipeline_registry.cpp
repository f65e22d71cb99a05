// The pipeline registry (see pipeline.h): the one place that knows every pipeline by name.
#include <functional>
#include <map>

#include "pipelines/cartoon/cartoon_pipelines.h"
#include "pipelines/deferred/deferred_pipelines.h"
#include "pipelines/lambert_pipeline.h"
#include "pipelines/universal/universal_pipeline.h"
#include "util/error.h"

namespace ontile {
namespace {

const std::map<std::string, std::function<std::unique_ptr<Pipeline>()>>& registry() {
  static const std::map<std::string, std::function<std::unique_ptr<Pipeline>()>> r = {
      {"lambert", [] { return std::make_unique<LambertPipeline>(); }},
      {"universal", [] { return make_universal_pipeline(); }},
      {"cartoon", [] { return std::make_unique<CartoonPipeline>(false); }},
      {"cartoon-multipass", [] { return std::make_unique<CartoonPipeline>(true); }},
      {"cartoon-hull", [] { return std::make_unique<CartoonHullPipeline>(); }},
      {"deferred-classic", [] { return std::make_unique<DeferredPipeline>(false); }},
      {"deferred-subpass", [] { return std::make_unique<DeferredPipeline>(true); }},
      {"forward", [] { return std::make_unique<ForwardPipeline>(); }},
  };
  return r;
}

}  // namespace

std::string PipelineOptions::take(const std::string& key, const std::string& fallback) const {
  taken_.insert(key);
  const auto it = values_.find(key);
  return it == values_.end() ? fallback : it->second;
}

void PipelineOptions::reject_unknown(const std::string& pipeline) const {
  for (const auto& [key, value] : values_) {
    if (!taken_.count(key)) throw Error("pipeline '" + pipeline + "' has no option '" + key + "'");
  }
}

std::vector<std::string> pipeline_names() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : registry()) names.push_back(name);
  return names;
}

std::unique_ptr<Pipeline> make_pipeline(const std::string& name) {
  const auto it = registry().find(name);
  if (it == registry().end()) {
    std::string valid;
    for (const auto& n : pipeline_names()) valid += (valid.empty() ? "" : ", ") + n;
    throw Error("unknown pipeline '" + name + "' (valid: " + valid + ")");
  }
  return it->second();
}

}  // namespace ontile
