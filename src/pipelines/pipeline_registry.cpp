// The pipeline registry (see pipeline.h): the one place that knows every pipeline by name.
#include <functional>
#include <map>

#include "pipelines/lambert_pipeline.h"
#include "util/error.h"

namespace ontile {
namespace {

const std::map<std::string, std::function<std::unique_ptr<Pipeline>()>>& registry() {
  static const std::map<std::string, std::function<std::unique_ptr<Pipeline>()>> r = {
      {"lambert", [] { return std::make_unique<LambertPipeline>(); }},
  };
  return r;
}

}  // namespace

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
