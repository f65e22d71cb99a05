// Test helper: analytic depth-buffer precision. Says whether two view-perpendicular surfaces at
// view distances d and d + s stay ordered in a D32F, D24 or D16 depth buffer under a standard
// (near -> 0) or reversed (near -> 1) perspective projection, including float rounding.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>

#include "raster/pixel_format.h"

namespace ontile::test {

enum class DepthConvention { Standard, Reversed };
enum class DepthVerdict { Resolvable, Unresolvable, Marginal };

struct DepthSetup {
  double near = 0.1, far = 100.0;  // far may be +infinity for a reversed projection
  DepthConvention convention = DepthConvention::Reversed;
  PixelFormat format = PixelFormat::D32_FLOAT;
};

// Window-space depth of a surface at view distance d (> 0): the [0, 1] projections of
// camera_matrices.cpp, with near and far swapped for Reversed (Vulkan depth range [0, 1]).
//   standard: far (d - near) / ((far - near) d)     reversed: near (far - d) / ((far - near) d)
inline double window_depth(const DepthSetup& s, double d) {
  if (s.convention == DepthConvention::Reversed) {
    if (std::isinf(s.far)) return s.near / d;
    return s.near * (s.far - d) / ((s.far - s.near) * d);
  }
  return s.far * (d - s.near) / ((s.far - s.near) * d);
}

// The clip-space z and w at distance d (what a vertex shader computes in double).
inline void clip_z_w(const DepthSetup& s, double d, double& z, double& w) {
  w = d;
  z = window_depth(s, d) * d;
}

// Bound on |computed - exact| depth: clip z and w are each rounded to float once (a
// double-precision model-view-projection), and the rasterizer rounds z / w to float
// (triangle_setup.cpp): three roundings of 2^-24 relative each, bounded by 4 * 2^-24.
inline double computed_depth_error(double depth) { return 4.0 * std::ldexp(std::abs(depth), -24); }

namespace detail {
inline float float_down(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}
inline float float_up(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}
// The range of stored values a computed depth in [lo, hi] can give, as D32F floats or as UNORM
// codes (Vulkan fixed-point conversion: round to nearest), both widened to double.
inline void stored_range(PixelFormat format, double lo, double hi, double& stored_lo, double& stored_hi) {
  if (format == PixelFormat::D32_FLOAT) {
    stored_lo = detail::float_down(lo);
    stored_hi = detail::float_up(hi);
    return;
  }
  const int bits = format == PixelFormat::D16_UNORM ? 16 : 24;
  stored_lo = float_to_unorm(detail::float_down(lo), bits);
  stored_hi = float_to_unorm(detail::float_up(hi), bits);
}
}  // namespace detail

// Resolvable: every possible stored value of the nearer surface beats every possible stored
// value of the farther one. Unresolvable: both can only store one and the same value (the
// depth test then sees equal depths: z-fighting decided by the compare op alone). Marginal:
// anything in between (rounding decides).
inline DepthVerdict classify_separation(const DepthSetup& s, double distance, double separation) {
  const double z_near = window_depth(s, distance), z_far = window_depth(s, distance + separation);
  double near_lo, near_hi, far_lo, far_hi;
  detail::stored_range(s.format, z_near - computed_depth_error(z_near), z_near + computed_depth_error(z_near),
                       near_lo, near_hi);
  detail::stored_range(s.format, z_far - computed_depth_error(z_far), z_far + computed_depth_error(z_far),
                       far_lo, far_hi);
  const bool ordered = s.convention == DepthConvention::Reversed ? near_lo > far_hi : near_hi < far_lo;
  if (ordered) return DepthVerdict::Resolvable;
  if (near_lo == near_hi && far_lo == far_hi && near_lo == far_lo) return DepthVerdict::Unresolvable;
  return DepthVerdict::Marginal;
}

}  // namespace ontile::test
