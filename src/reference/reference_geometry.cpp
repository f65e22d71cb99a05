// Embree 3 scene of the reference renderer (see reference_geometry.h). Every hit goes through
// a context filter that records it and rejects it, so one traversal returns all crossings; the
// caller then picks surfaces in a fixed order, independent of how Embree built its BVH.
#include "reference/reference_geometry.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "util/error.h"

namespace ontile {

struct ReferenceGeometry::EmbreeHandles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

namespace {

// Ray state the filter reads; RTCIntersectContext must come first (Embree passes it back).
struct CollectContext {
  RTCIntersectContext embree;
  const ReferenceGeometry* geometry = nullptr;
  glm::dvec3 origin{0.0}, direction{0.0};
  double t_max = 0.0;
  std::vector<RayCandidate>* out = nullptr;
};

void throw_on_device_error(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) {
    throw Error(std::string("reference renderer: Embree ") + what + " failed (RTCError " +
                std::to_string(static_cast<int>(error)) + ")");
  }
}

void record_and_reject_hit(const RTCFilterFunctionNArguments* args) {
  const auto* ctx = reinterpret_cast<const CollectContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    args->valid[i] = 0;  // reject: traversal goes on and reports every crossing
    const uint32_t renderer = RTCHitN_geomID(args->hit, args->N, i);
    const uint32_t triangle = RTCHitN_primID(args->hit, args->N, i);
    const CullMode cull = ctx->geometry->cull_mode(renderer);
    const std::array<glm::dvec3, 3> p = ctx->geometry->triangle_world(renderer, triangle);
    const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double n_dot_d = glm::dot(n, ctx->direction);
    if (n_dot_d == 0.0) continue;  // edge-on: zero area on screen, the rasterizer draws nothing
    // glTF front faces are counter-clockwise: their normal (right-hand rule) faces the viewer.
    const bool front_facing = n_dot_d < 0.0;
    if ((cull == CullMode::Back && !front_facing) || (cull == CullMode::Front && front_facing)) continue;
    const double t = glm::dot(n, p[0] - ctx->origin) / n_dot_d;
    if (!(t >= 0.0 && t <= ctx->t_max)) continue;
    ctx->out->push_back({t, renderer, triangle, ctx->geometry->primitive_id_base(renderer) + triangle, front_facing});
  }
}

}  // namespace

ReferenceGeometry::ReferenceGeometry(const std::vector<Renderer>& renderers,
                                     const std::vector<CullMode>& cull_modes) {
  if (cull_modes.size() != renderers.size()) {
    throw Error("reference renderer: " + std::to_string(cull_modes.size()) + " cull modes for " +
                std::to_string(renderers.size()) + " renderers");
  }
  renderers_.resize(renderers.size());
  for (size_t i = 0; i < renderers.size(); ++i) {
    RendererGeometry& g = renderers_[i];
    g.mesh = renderers[i].mesh;
    g.primitive_id_base = renderers[i].primitive_id_base;
    g.cull = cull_modes[i];
    g.world_positions.reserve(g.mesh->positions.size());
    for (const glm::vec3& p : g.mesh->positions) {
      g.world_positions.push_back(glm::dvec3(renderers[i].world * glm::dvec4(glm::dvec3(p), 1.0)));
    }
    triangle_count_ += g.mesh->triangle_count();
  }
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-low);
  for (const RendererGeometry& g : renderers_) {
    for (const glm::dvec3& p : g.world_positions) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  }
  if (low.x <= high.x) {
    // The bounds' centre rounded to a multiple of a power of two `grid` at least twice the
    // scene's extent: 0 for a scene around the origin (Embree gets world coordinates, as
    // before), and for a scene moved by a multiple of `grid` exactly that offset, so its float
    // coordinates are the unmoved scene's.
    const glm::dvec3 extent = high - low;
    const double grid = std::exp2(std::ceil(std::log2(std::max(
        {2.0 * std::max({extent.x, extent.y, extent.z}), 1.0}))));
    embree_origin_ = glm::round(0.5 * (low + high) / grid) * grid;
  }
  if (triangle_count_ >= kMaxExactFloatPrimitiveIds) {
    throw Error("reference renderer: the scene has " + std::to_string(triangle_count_) +
                " triangles; primitive-id AOVs are floats, exact only below 2^24 = 16777216");
  }

  embree_ = new EmbreeHandles;
  embree_->device = rtcNewDevice(nullptr);
  if (!embree_->device) {
    delete embree_;
    throw Error("reference renderer: cannot create an Embree device");
  }
  embree_->scene = rtcNewScene(embree_->device);
  // Robust mode: watertight edges, so a ray through an edge shared by two triangles hits one.
  rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);
  for (size_t i = 0; i < renderers_.size(); ++i) {
    const RendererGeometry& g = renderers_[i];
    const uint32_t triangles = g.mesh->triangle_count();
    if (triangles == 0 || g.world_positions.empty()) continue;
    RTCGeometry geom = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), g.world_positions.size()));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles));
    throw_on_device_error(embree_->device, "buffer allocation");
    for (size_t v = 0; v < g.world_positions.size(); ++v) {
      for (int c = 0; c < 3; ++c) {
        vertices[3 * v + c] = static_cast<float>(g.world_positions[v][c] - embree_origin_[c]);
      }
    }
    std::copy(g.mesh->indices.begin(), g.mesh->indices.begin() + 3 * size_t{triangles}, indices);
    rtcCommitGeometry(geom);
    // The geometry id is the renderer index, so hits map back without a table.
    rtcAttachGeometryByID(embree_->scene, geom, static_cast<unsigned>(i));
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(embree_->scene);
  throw_on_device_error(embree_->device, "scene build");
}

ReferenceGeometry::~ReferenceGeometry() {
  if (!embree_) return;
  if (embree_->scene) rtcReleaseScene(embree_->scene);
  rtcReleaseDevice(embree_->device);
  delete embree_;
}

void ReferenceGeometry::intersect_all(const glm::dvec3& origin, const glm::dvec3& direction,
                                      double t_max, std::vector<RayCandidate>& out) const {
  out.clear();
  CollectContext ctx;
  rtcInitIntersectContext(&ctx.embree);
  ctx.embree.filter = &record_and_reject_hit;
  ctx.geometry = this;
  ctx.origin = origin;
  ctx.direction = direction;
  ctx.t_max = t_max;
  ctx.out = &out;
  RTCRayHit rh{};
  rh.ray.org_x = static_cast<float>(origin.x - embree_origin_.x);
  rh.ray.org_y = static_cast<float>(origin.y - embree_origin_.y);
  rh.ray.org_z = static_cast<float>(origin.z - embree_origin_.z);
  rh.ray.dir_x = static_cast<float>(direction.x);
  rh.ray.dir_y = static_cast<float>(direction.y);
  rh.ray.dir_z = static_cast<float>(direction.z);
  rh.ray.tnear = 0.0f;
  // Embree's float distances differ from the exact ones by rounding: widen its interval by a
  // relative margin and let the filter apply the exact bounds.
  rh.ray.tfar = std::isinf(t_max) ? std::numeric_limits<float>::infinity()
                                  : static_cast<float>(t_max * (1.0 + 1e-5));
  rh.ray.mask = ~0u;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(embree_->scene, &ctx.embree, &rh);
  // A triangle in several BVH leaves (spatial splits) is reported once per leaf.
  std::sort(out.begin(), out.end(), [](const RayCandidate& a, const RayCandidate& b) {
    return a.t != b.t ? a.t < b.t : a.primitive_id < b.primitive_id;
  });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const RayCandidate& a, const RayCandidate& b) { return a.primitive_id == b.primitive_id; }),
            out.end());
}

std::array<glm::dvec3, 3> ReferenceGeometry::triangle_world(uint32_t renderer, uint32_t triangle) const {
  const RendererGeometry& g = renderers_[renderer];
  const uint32_t* idx = &g.mesh->indices[3 * size_t{triangle}];
  return {g.world_positions[idx[0]], g.world_positions[idx[1]], g.world_positions[idx[2]]};
}

std::array<uint32_t, 3> ReferenceGeometry::triangle_indices(uint32_t renderer, uint32_t triangle) const {
  const uint32_t* idx = &renderers_[renderer].mesh->indices[3 * size_t{triangle}];
  return {idx[0], idx[1], idx[2]};
}

bool ReferenceGeometry::locate(uint32_t primitive_id, uint32_t& renderer, uint32_t& triangle) const {
  // Bases increase in renderer order: the owner is the last renderer whose base <= id.
  const auto it = std::upper_bound(renderers_.begin(), renderers_.end(), primitive_id,
                                   [](uint32_t id, const RendererGeometry& g) { return id < g.primitive_id_base; });
  if (it == renderers_.begin()) return false;
  const RendererGeometry& g = *(it - 1);
  if (primitive_id - g.primitive_id_base >= g.mesh->triangle_count()) return false;
  renderer = static_cast<uint32_t>(it - 1 - renderers_.begin());
  triangle = primitive_id - g.primitive_id_base;
  return true;
}

}  // namespace ontile
