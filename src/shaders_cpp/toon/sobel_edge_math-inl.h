// The Sobel edge test of one vector of fragments (sobel_edge_kernel.h, find_edges), shared by
// the kernel that gathers each tap from the grid and the one that loads whole tap rows, so both
// run the same operations in the same order on every lane (re-included per Highway target:
// toggling guard as in raster/lane_bits-inl.h).
#if defined(ONTILE_SOBEL_EDGE_MATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ONTILE_SOBEL_EDGE_MATH_INL_H_
#undef ONTILE_SOBEL_EDGE_MATH_INL_H_
#else
#define ONTILE_SOBEL_EDGE_MATH_INL_H_
#endif

#include <hwy/highway.h>

#include "shaders_cpp/toon/sobel_edge_kernel.h"

HWY_BEFORE_NAMESPACE();
namespace ontile::sobel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The Sobel kernels on tap values t[k] (sobel_magnitude): ((r0 + r2) + 2 r1) of differences.
template <class DF, class VF = hn::Vec<DF>>
HWY_INLINE VF sobel_x(DF df, const VF t[kTaps]) {
  return hn::Add(hn::Add(hn::Sub(t[2], t[0]), hn::Sub(t[8], t[6])),
                 hn::Mul(hn::Set(df, 2.0f), hn::Sub(t[5], t[3])));
}
template <class DF, class VF = hn::Vec<DF>>
HWY_INLINE VF sobel_y(DF df, const VF t[kTaps]) {
  return hn::Add(hn::Add(hn::Sub(t[6], t[0]), hn::Sub(t[8], t[2])),
                 hn::Mul(hn::Set(df, 2.0f), hn::Sub(t[7], t[1])));
}
// glm::dot of two 3-vectors: (x * x' + y * y') + z * z'.
template <class VF>
HWY_INLINE VF dot3(VF ax, VF ay, VF az, VF bx, VF by, VF bz) {
  return hn::Add(hn::Add(hn::Mul(ax, bx), hn::Mul(ay, by)), hn::Mul(az, bz));
}

// The edge test of the fragments on the lanes of df at (u, v): tap k's view distance is
// linear_z(k), its stored depth depth(k), channel c of its decoded normal normal(c, k). Sets
// depth_edge and edge, and nearest (the first tap of the smallest stored depth, the centre
// keeping ties) where a lane has an edge (the centre tap elsewhere).
template <class DF, class LinearZ, class Depth, class Normal>
HWY_INLINE void edge_lanes(DF df, hn::Vec<DF> u, hn::Vec<DF> v, const EdgeTest& test,
                           const LinearZ& linear_z, const Depth& depth, const Normal& normal,
                           hn::Mask<DF>& depth_edge_out, hn::Mask<DF>& edge_out,
                           hn::Vec<hn::RebindToSigned<DF>>& nearest_out) {
  using VF = hn::Vec<DF>;
  const hn::RebindToSigned<DF> di;
  VF z[kTaps];
  for (int k = 0; k < kTaps; ++k) z[k] = linear_z(k);
  VF depth_limit = hn::Mul(hn::Set(df, test.depth_limit_scale), z[kCentreTap]);
  if (test.has_normal) {
    // grazing_cosine: the view ray through the pixel against the centre's normal.
    const VF nx = normal(0, kCentreTap);
    const VF ny = normal(1, kCentreTap);
    const VF nz = normal(2, kCentreTap);
    const VF one = hn::Set(df, 1.0f), two = hn::Set(df, 2.0f), minus_one = hn::Set(df, -1.0f);
    const VF rx = hn::Mul(hn::Set(df, test.view_ray_scale.x), hn::Sub(hn::Mul(two, u), one));
    const VF ry = hn::Mul(hn::Set(df, test.view_ray_scale.y), hn::Sub(one, hn::Mul(two, v)));
    const VF normal_len = hn::Sqrt(dot3(nx, ny, nz, nx, ny, nz));
    const VF ray_len = hn::Sqrt(dot3(rx, ry, minus_one, rx, ry, minus_one));
    const VF cosine =
        hn::Div(hn::Abs(dot3(nx, ny, nz, rx, ry, minus_one)), hn::Mul(normal_len, ray_len));
    const VF min_cosine = hn::Set(df, test.min_grazing_cosine);
    VF grazing = hn::IfThenElse(hn::Gt(cosine, min_cosine), cosine, min_cosine);
    grazing = hn::IfThenElse(hn::Gt(normal_len, hn::Zero(df)), grazing, min_cosine);
    depth_limit = hn::Div(depth_limit, grazing);
  }
  const VF gx = sobel_x(df, z), gy = sobel_y(df, z);
  const hn::Mask<DF> depth_edge =
      hn::Gt(hn::Sqrt(hn::Add(hn::Mul(gx, gx), hn::Mul(gy, gy))), depth_limit);
  hn::Mask<DF> edge = depth_edge;
  if (test.has_normal && !hn::AllTrue(df, depth_edge)) {
    // sobel_vector_magnitude where depth found no edge.
    VF gxs[3], gys[3];
    for (int c = 0; c < 3; ++c) {
      VF t[kTaps];
      for (int k = 0; k < kTaps; ++k) t[k] = normal(c, k);
      gxs[c] = sobel_x(df, t);
      gys[c] = sobel_y(df, t);
    }
    const VF magnitude = hn::Sqrt(hn::Add(dot3(gxs[0], gxs[1], gxs[2], gxs[0], gxs[1], gxs[2]),
                                          dot3(gys[0], gys[1], gys[2], gys[0], gys[1], gys[2])));
    edge = hn::Or(edge, hn::Gt(magnitude, hn::Set(df, test.normal_threshold)));
  }
  // The first tap of the smallest stored depth, the centre keeping ties: only an edge reads
  // it (the border colour), so vectors without one skip its loads.
  auto nearest = hn::Set(di, kCentreTap);
  if (!hn::AllFalse(df, edge)) {
    VF nearest_depth = depth(kCentreTap);
    for (int k = 0; k < kTaps; ++k) {
      if (k == kCentreTap) continue;
      const VF d = depth(k);
      const hn::Mask<DF> closer = hn::Lt(d, nearest_depth);
      nearest_depth = hn::IfThenElse(closer, d, nearest_depth);
      nearest = hn::IfThenElse(hn::RebindMask(di, closer), hn::Set(di, k), nearest);
    }
  }
  depth_edge_out = depth_edge;
  edge_out = edge;
  nearest_out = nearest;
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile::sobel
HWY_AFTER_NAMESPACE();

#endif  // ONTILE_SOBEL_EDGE_MATH_INL_H_
