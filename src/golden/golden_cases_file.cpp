// Reads a user's golden cases from JSON (see golden_cases_file.h; schema in docs/golden.md).
// Strict: an unknown key is an error, so a misspelt "tolerence" cannot silently mean "exact".
#include "golden/golden_cases_file.h"

#include <cctype>
#include <charconv>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "util/error.h"

namespace ontile {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Errors say where: "FILE: cases[2] (name): problem".
struct Where {
  const fs::path& file;
  std::string at;
  [[noreturn]] void fail(const std::string& problem) const {
    throw Error(file.string() + ": " + (at.empty() ? "" : at + ": ") + problem);
  }
};

void reject_unknown_keys(const json& object, const std::set<std::string>& known, const Where& where) {
  for (const auto& [key, value] : object.items()) {
    if (!known.count(key)) {
      std::string names;
      for (const std::string& k : known) names += (names.empty() ? "" : ", ") + k;
      where.fail("unknown key \"" + key + "\" (expected " + names + ")");
    }
  }
}

const json& require(const json& object, const char* key, json::value_t type, const char* type_name,
                    const Where& where) {
  if (!object.contains(key)) where.fail(std::string("\"") + key + "\" is required");
  const json& value = object.at(key);
  const bool ok = type == json::value_t::number_integer ? value.is_number_integer() : value.type() == type;
  if (!ok) where.fail(std::string("\"") + key + "\" must be " + type_name);
  return value;
}

// A case name is a file stem: letters, digits, '.', '_' and '-', not starting with '.'.
bool valid_name(const std::string& name) {
  if (name.empty() || name.front() == '.') return false;
  for (char c : name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) return false;
  }
  return true;
}

// "WxH" with decimal sides; the range is checked when the case renders (render_frame).
void parse_size(const std::string& text, GoldenCase& c, const Where& where) {
  const size_t x = text.find('x');
  const auto side = [&](std::string_view digits, int& out) {
    if (digits.empty() || digits.size() > 5) return false;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), out);
    return ec == std::errc() && end == digits.data() + digits.size() && out >= 1;
  };
  if (x == std::string::npos || !side(std::string_view(text).substr(0, x), c.width_px) ||
      !side(std::string_view(text).substr(x + 1), c.height_px)) {
    where.fail("\"size\" '" + text + "': expected WIDTHxHEIGHT with positive integers, e.g. 480x270");
  }
}

std::string option_value(const json& value, const std::string& key, const Where& where) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_integer()) return std::to_string(value.get<int64_t>());
  if (value.is_boolean()) return value.get<bool>() ? "on" : "off";
  where.fail("option \"" + key + "\" must be a string, an integer or a boolean");
}

GoldenCase read_case(const json& item, const fs::path& folder, const Where& where) {
  if (!item.is_object()) where.fail("a case must be an object");
  reject_unknown_keys(item, {"name", "scene", "pipeline", "size", "camera", "options", "reference", "tolerance"},
                      where);
  GoldenCase c;
  c.name = require(item, "name", json::value_t::string, "a string", where).get<std::string>();
  const Where named{where.file, where.at + " (" + c.name + ")"};
  if (!valid_name(c.name)) named.fail("\"name\" must be letters, digits, '.', '_' or '-' (it names files)");
  c.scene = folder / require(item, "scene", json::value_t::string, "a string", named).get<std::string>();
  std::error_code ec;
  if (!fs::is_regular_file(c.scene, ec)) named.fail("scene " + c.scene.string() + " not found");
  c.pipeline = require(item, "pipeline", json::value_t::string, "a string", named).get<std::string>();
  c.reference = folder / require(item, "reference", json::value_t::string, "a string", named).get<std::string>();
  if (item.contains("size")) {
    parse_size(require(item, "size", json::value_t::string, "a string", named).get<std::string>(), c, named);
  }
  if (item.contains("camera")) {
    const int64_t camera = require(item, "camera", json::value_t::number_integer, "an integer", named).get<int64_t>();
    if (camera < 0 || camera > 1'000'000) named.fail("\"camera\" must be a camera index (0, 1, ...)");
    c.camera_index = static_cast<int>(camera);
  }
  if (item.contains("options")) {
    const json& options = require(item, "options", json::value_t::object, "an object", named);
    for (const auto& [key, value] : options.items()) c.options.emplace_back(key, option_value(value, key, named));
  }
  if (item.contains("tolerance")) {
    const json& tolerance = require(item, "tolerance", json::value_t::object, "an object", named);
    reject_unknown_keys(tolerance, {"max_abs", "max_pixels"}, named);
    if (tolerance.contains("max_abs")) {
      const json& max_abs = tolerance.at("max_abs");
      if (!max_abs.is_number() || max_abs.get<double>() < 0.0) named.fail("\"max_abs\" must be a number >= 0");
      c.tolerance.max_abs = max_abs.get<double>();
    }
    if (tolerance.contains("max_pixels")) {
      const json& max_pixels = tolerance.at("max_pixels");
      if (!max_pixels.is_number_integer() || max_pixels.get<int64_t>() < 0) {
        named.fail("\"max_pixels\" must be an integer >= 0");
      }
      c.tolerance.max_pixels = max_pixels.get<uint64_t>();
    }
  }
  return c;
}

}  // namespace

std::vector<GoldenCase> read_golden_cases_file(const fs::path& json_file) {
  const Where top{json_file, ""};
  std::error_code ec;
  if (!fs::is_regular_file(json_file, ec)) top.fail(fs::exists(json_file, ec) ? "not a regular file" : "file not found");
  std::ifstream stream(json_file, std::ios::binary);
  std::stringstream text;
  text << stream.rdbuf();
  if (!stream) top.fail("cannot read the file");
  json document;
  try {
    document = json::parse(text.str());
  } catch (const json::parse_error& e) {
    top.fail(std::string("malformed JSON: ") + e.what());
  }
  if (!document.is_object()) top.fail("expected an object with a \"cases\" array");
  reject_unknown_keys(document, {"cases"}, top);
  const json& items = require(document, "cases", json::value_t::array, "an array", top);
  if (items.empty()) top.fail("\"cases\" is empty");
  const fs::path folder = json_file.parent_path();
  std::vector<GoldenCase> cases;
  std::set<std::string> names;
  for (size_t i = 0; i < items.size(); ++i) {
    const Where where{json_file, "cases[" + std::to_string(i) + "]"};
    GoldenCase c = read_case(items[i], folder, where);
    if (!names.insert(c.name).second) where.fail("duplicate case name \"" + c.name + "\"");
    cases.push_back(std::move(c));
  }
  return cases;
}

}  // namespace ontile
