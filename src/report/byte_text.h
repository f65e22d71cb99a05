// Byte counts as people read them in the HTML report: "812 B", "12.5 KiB", "3.52 MiB", and
// with thousands separators ("3,686,400") where the exact count matters.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>

namespace ontile {

inline std::string bytes_text(uint64_t bytes) {
  char buf[32];
  if (bytes < 1024) {
    std::snprintf(buf, sizeof buf, "%llu B", static_cast<unsigned long long>(bytes));
  } else if (bytes < 1024 * 1024) {
    std::snprintf(buf, sizeof buf, "%.1f KiB", static_cast<double>(bytes) / 1024.0);
  } else {
    std::snprintf(buf, sizeof buf, "%.2f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  }
  return buf;
}

inline std::string grouped_bytes(uint64_t bytes) {
  const std::string digits = std::to_string(bytes);
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace ontile
