// Toon settings from material extras (see toon_settings.h).
#include "pipelines/cartoon/toon_settings.h"

#include <nlohmann/json.hpp>

#include "util/error.h"

namespace ontile {
namespace {

[[noreturn]] void bad(const Material& m, const std::string& what) {
  throw Error("material '" + m.name + "': extras.ontile." + what);
}

template <int N>
glm::vec<N, float> read_color(const Material& m, const nlohmann::json& j, const char* key,
                              glm::vec<N, float> fallback) {
  if (!j.contains(key)) return fallback;
  const auto& v = j[key];
  if (!v.is_array() || (v.size() != N && !(N == 4 && v.size() == 3))) {
    bad(m, std::string(key) + " must be an array of " + std::to_string(N) + " numbers");
  }
  glm::vec<N, float> out(1.0f);
  for (size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_number()) bad(m, std::string(key) + " must contain numbers");
    out[static_cast<int>(i)] = v[i].get<float>();
  }
  return out;
}

}  // namespace

ToonSettings toon_settings(const Material& m) {
  ToonSettings s;
  // Defaults from the PBR material: lit = base colour, shadow = half of it.
  s.lit_color = glm::vec3(m.base_color_factor);
  s.shadow_color = s.lit_color * 0.5f;
  if (m.extras_json.empty()) return s;
  nlohmann::json extras = nlohmann::json::parse(m.extras_json, nullptr, false);
  if (extras.is_discarded() || !extras.is_object() || !extras.contains("ontile")) return s;
  const nlohmann::json& j = extras["ontile"];
  if (!j.is_object()) bad(m, "must be an object");
  if (j.contains("shader")) {
    const std::string shader = j["shader"].is_string() ? j["shader"].get<std::string>() : "";
    if (shader == "cel") s.shading = ToonSettings::Shading::Cel;
    else if (shader == "matcap") s.shading = ToonSettings::Shading::MatCap;
    else if (shader == "toon_env") s.shading = ToonSettings::Shading::ToonEnv;
    else bad(m, "shader '" + shader + "' is not cel, matcap or toon_env");
  }
  if (j.contains("steps")) {
    if (!j["steps"].is_number_integer() || j["steps"].get<int>() < 1 || j["steps"].get<int>() > 64) {
      bad(m, "steps must be an integer in 1..64");
    }
    s.steps = j["steps"].get<int>();
  }
  if (j.contains("step_size")) {
    if (!j["step_size"].is_number() || !(j["step_size"].get<float>() > 0.0f)) bad(m, "step_size must be > 0");
    s.step_size = j["step_size"].get<float>();
  }
  s.lit_color = read_color<3>(m, j, "lit_color", s.lit_color);
  s.shadow_color = read_color<3>(m, j, "shadow_color", s.shadow_color);
  s.border_color = read_color<4>(m, j, "border_color", s.border_color);
  if (j.contains("matcap")) {
    if (!j["matcap"].is_string()) bad(m, "matcap must be a string");
    s.matcap = j["matcap"].get<std::string>();
  }
  if (j.contains("outline_thickness")) {
    if (!j["outline_thickness"].is_number() || j["outline_thickness"].get<float>() < 0.0f) {
      bad(m, "outline_thickness must be >= 0");
    }
    s.outline_thickness = j["outline_thickness"].get<float>();
  }
  return s;
}

}  // namespace ontile
