// How the reference renderer shades a ray hit: with the very functors the lambert pipeline
// draws with (built by the Lit shader's ForwardLit factory from a DrawContext), on a 2x2 quad
// of rays whose helper lanes are extrapolated on the hit triangle's plane, as a rasterizer's are.
#pragma once
#include <memory>
#include <vector>

#include "context/scene_renderers.h"
#include "reference/reference_geometry.h"

namespace ontile {

// Which of the lambert pipeline's draw_renderers calls draws a renderer (its render queue).
enum class SurfaceClass {
  Opaque,       // opaque queue, never discards: the nearest hit wins
  AlphaTested,  // opaque queue, may discard: the nearest hit that is not discarded wins
  Blended,      // transparent queue: composited back to front over the opaque result
};

struct ReferenceDraw {
  DrawFunctors functors;  // vertex and fragment functors, as FrameExecutor builds them
  PassState state;        // the material's render state for the pass (cull, blend)
  SurfaceClass surface_class = SurfaceClass::Opaque;
};

// The lambert pipeline's scene as the reference sees it: renderers, their draws, the clear
// colour and the ray-tracing geometry (same triangles, same primitive ids, same culling).
struct LambertReferenceScene {
  std::unique_ptr<Shader> lit_shader;
  SceneRenderers renderers;
  std::vector<ReferenceDraw> draws;  // one per renderer
  std::unique_ptr<ReferenceGeometry> geometry;
  CameraMatrices camera;
  glm::vec4 clear_color{0.0f};
};

// Builds everything the lambert pipeline would build for a frame of width x height with this
// camera: Lit materials, lighting globals and one ForwardLit draw per renderer.
LambertReferenceScene make_lambert_reference_scene(const Scene& scene, const Camera& camera,
                                                   int width_px, int height_px);

// The rays of one 2x2 quad, lanes in QuadFragment order.
struct QuadRays {
  glm::dvec3 origin[kQuadLanes];
  glm::dvec3 direction[kQuadLanes];
};

struct QuadShading {
  QuadOutput output;                  // colour target 0 and discards, as the functor wrote them
  float depth[kQuadLanes] = {};       // clip z / w at each lane's point on the plane, [0, 1]
  glm::vec3 normal[kQuadLanes] = {};  // unit world-space shading normal facing the viewer
};

// Runs the vertex functor on the hit triangle's three vertices, interpolates the varyings at
// each lane's ray-plane intersection with exact (double) barycentrics, and calls the fragment
// functor once with lane_mask as the active lanes (the others are helper lanes).
void shade_hit_quad(const LambertReferenceScene& ref, const RayCandidate& hit, const QuadRays& rays,
                    int quad_x_px, int quad_y_px, uint8_t lane_mask, QuadShading& out);

}  // namespace ontile
