// x^5 for Schlick's Fresnel term with the bits of std::pow(x, 5.0f), cheaply: the double product
// x^2 x^2 x rounded to float is glibc's powf result except within 1/64 ulp of a rounding tie or
// outside the normal floats, where powf itself is called (docs/performance.md, "Schlick power").
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>

namespace ontile {

// The double's fraction bits a float drops (52 - 23); a tie of the float rounding has the top
// one of them set and the rest clear.
constexpr int kSchlickDroppedBits = 29;
// Half-width of the window around a tie, in units of the double's last bit: 2^23 of 2^29 per
// float ulp, 1/64 ulp. Over every finite float, glibc 2.36's powf(x, 5) and the rounded double
// product differ only within 0.0017 ulp of a tie, so the window keeps a margin of 9x.
constexpr uint64_t kSchlickTieWindow = uint64_t{1} << 23;
constexpr double kSchlickSmallestNormal = 0x1p-126;  // below: a subnormal float (double rounding)
constexpr double kSchlickLargest = 0x1p127;          // from here on: rounding towards overflow

// Whether the rounded double product is std::pow(x, 5.0f)'s value for x (a float's value).
inline bool schlick_power_is_exact(double x) {
  const double x2 = x * x;
  const double r = x2 * x2 * x;
  uint64_t bits;
  std::memcpy(&bits, &r, sizeof bits);
  const uint64_t dropped = bits & ((uint64_t{1} << kSchlickDroppedBits) - 1);
  const uint64_t tie = uint64_t{1} << (kSchlickDroppedBits - 1);
  const bool near_tie = dropped - (tie - kSchlickTieWindow) < 2 * kSchlickTieWindow;
  const double magnitude = std::fabs(r);
  const bool normal = r == 0.0 || (magnitude >= kSchlickSmallestNormal && magnitude < kSchlickLargest);
  return normal && !near_tie;
}

// std::pow(x, 5.0f), bit for bit.
inline float schlick_power(float x) {
  if (!schlick_power_is_exact(x)) return std::pow(x, 5.0f);
  const double xd = x, x2 = xd * xd;
  return static_cast<float>(x2 * x2 * xd);
}

// out[i] = schlick_power(x[i]) for i < count, on SIMD lanes (lighting_lanes.cpp).
void schlick_power_lanes(const float* x, int count, float* out);

}  // namespace ontile
