// Sweep error measures (see sweep_metrics.h).
#include "analysis/sweep_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>

#include "util/error.h"

namespace ontile {
namespace {

void check_size(const Surface& s, int width_px, int height_px, const char* what) {
  if (s.width() != width_px || s.height() != height_px) {
    throw Error(std::string("sweep: ") + what + " '" + s.name() + "' is " + std::to_string(s.width()) + "x" +
                std::to_string(s.height()) + ", expected " + std::to_string(width_px) + "x" +
                std::to_string(height_px));
  }
}

}  // namespace

ColorError color_error(const Surface& raster, const ReferenceImage& ref) {
  if (raster.format() != PixelFormat::RGBA8_SRGB) {
    throw Error(std::string("sweep: colour '") + raster.name() + "' is " + format_name(raster.format()) +
                ", the reference comparison needs rgba8_srgb");
  }
  check_size(raster, ref.width_px, ref.height_px, "colour");
  const std::vector<uint8_t>& bytes = raster.bytes();
  double abs_sum = 0.0, sq_sum = 0.0;
  ColorError e;
  const size_t pixels = size_t(ref.width_px) * ref.height_px;
  for (size_t i = 0; i < pixels; ++i) {
    for (int c = 0; c < 3; ++c) {
      const int diff = std::abs(int(bytes[4 * i + c]) - int(linear_to_srgb8(ref.color[i][c])));
      abs_sum += diff;
      sq_sum += double(diff) * diff;
      e.max_abs = std::max(e.max_abs, diff);
    }
  }
  const double samples = 3.0 * double(pixels);
  e.mean_abs = samples > 0 ? abs_sum / samples : 0.0;
  const double mse = samples > 0 ? sq_sum / samples : 0.0;
  e.psnr_db = mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
  return e;
}

double primitive_id_mismatch(const Surface& ids, const Surface& other) {
  check_size(other, ids.width(), ids.height(), "primitive ids");
  uint64_t differ = 0;
  for (int y = 0; y < ids.height(); ++y) {
    for (int x = 0; x < ids.width(); ++x) differ += ids.read(x, y).x != other.read(x, y).x;
  }
  return double(differ) / (double(ids.width()) * ids.height());
}

double primitive_id_mismatch(const Surface& ids, const ReferenceImage& ref) {
  check_size(ids, ref.width_px, ref.height_px, "primitive ids");
  uint64_t differ = 0;
  for (int y = 0; y < ref.height_px; ++y) {
    for (int x = 0; x < ref.width_px; ++x) {
      differ += ids.read(x, y).x != ref.primitive_id[size_t(y) * ref.width_px + x];
    }
  }
  return double(differ) / (double(ref.width_px) * ref.height_px);
}

double angle_between_deg(const glm::vec3& a, const glm::vec3& b) {
  const glm::dvec3 da(a), db(b);
  return std::atan2(glm::length(glm::cross(da, db)), glm::dot(da, db)) * 180.0 / std::numbers::pi;
}

namespace {

// Angular error of the decoded normals over the pixels where `truth` gives a normal (the
// callback returns false elsewhere).
template <class Truth>
NormalError angular_error(const Surface& stored, NormalStorage storage, Truth&& truth) {
  NormalError e;
  double sum = 0.0;
  for (int y = 0; y < stored.height(); ++y) {
    for (int x = 0; x < stored.width(); ++x) {
      glm::vec3 expected;
      if (!truth(x, y, expected)) continue;
      const double deg = angle_between_deg(decode_normal(storage, stored.read(x, y)), expected);
      ++e.pixels;
      sum += deg;
      e.max_deg = std::max(e.max_deg, deg);
    }
  }
  e.mean_deg = e.pixels ? sum / double(e.pixels) : 0.0;
  return e;
}

}  // namespace

NormalError normal_error(const Surface& stored, NormalStorage storage, const Surface& ids,
                         const ReferenceImage& ref) {
  check_size(stored, ref.width_px, ref.height_px, "normals");
  check_size(ids, ref.width_px, ref.height_px, "primitive ids");
  return angular_error(stored, storage, [&](int x, int y, glm::vec3& expected) {
    const size_t i = size_t(y) * ref.width_px + x;
    const float id = ids.read(x, y).x;
    if (id < 0.0f || id != ref.primitive_id[i]) return false;
    expected = ref.normal[i];
    return true;
  });
}

NormalError normal_error(const Surface& stored, NormalStorage storage, const Surface& ids,
                         const Surface& float_normals, const Surface& float_ids) {
  for (const Surface* s : {&ids, &float_normals, &float_ids}) check_size(*s, stored.width(), stored.height(), "normals");
  return angular_error(stored, storage, [&](int x, int y, glm::vec3& expected) {
    const float id = ids.read(x, y).x;
    if (id < 0.0f || id != float_ids.read(x, y).x) return false;
    expected = glm::vec3(float_normals.read(x, y));
    return true;
  });
}

}  // namespace ontile
