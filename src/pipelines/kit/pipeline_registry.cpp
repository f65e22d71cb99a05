// The pipeline registry (see pipeline.h): pipelines add themselves, the CLI lists them by name.
#include <cstdio>
#include <cstdlib>
#include <map>

#include "pipelines/kit/pipeline.h"
#include "util/error.h"

namespace ontile {
namespace {

// Filled by PipelineRegistration objects during static initialisation; a function-local static
// so that it exists before the first registration, whatever the order of translation units.
std::map<std::string, PipelineFactory>& registry() {
  static std::map<std::string, PipelineFactory> r;
  return r;
}

}  // namespace

PipelineRegistration::PipelineRegistration(const std::string& name, PipelineFactory factory) {
  if (!registry().emplace(name, std::move(factory)).second) {
    std::fprintf(stderr, "ontile: pipeline '%s' registered twice\n", name.c_str());
    std::abort();
  }
}

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
