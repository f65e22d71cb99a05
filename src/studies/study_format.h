// Helpers the study verbs share to format their tables: fixed decimals, a byte category of a
// row (0 when absent), and a row found by its variant label.
#pragma once
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace ontile::study_format {

constexpr double kMiB = 1024.0 * 1024.0;

inline std::string fixed(double v, int decimals) {
  char s[32];
  std::snprintf(s, sizeof s, "%.*f", decimals, v);
  return s;
}

// Any row with a bytes_by_category map.
template <class Row>
uint64_t category(const Row& r, const char* name) {
  const auto it = r.bytes_by_category.find(name);
  return it == r.bytes_by_category.end() ? 0 : it->second;
}

// The row whose variant has this label, or null (rows with a `variant.label`).
template <class Row>
const Row* find_row(const std::vector<Row>& rows, const std::string& label) {
  for (const Row& r : rows) {
    if (r.variant.label == label) return &r;
  }
  return nullptr;
}

}  // namespace ontile::study_format
