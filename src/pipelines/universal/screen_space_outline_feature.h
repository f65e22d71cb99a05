// ScreenSpaceOutline: a renderer feature of the universal pipeline that gives it cartoon edges.
// It asks for the DepthNormals prepass and the colour copy, then blits the copy back onto the
// camera colour through the Sobel edge functor (shaders_cpp/toon/sobel_edge_shader.h).
#pragma once
#include <memory>

#include <glm/glm.hpp>

#include "pipelines/universal/renderer_feature.h"

namespace ontile {

struct ScreenSpaceOutlineSettings {
  int event = RenderPassEvent::AfterRenderingTransparents;
  // The Sobel functor's defaults (SobelEdgeParams).
  float thickness_px = 1.0f;
  float depth_threshold = 0.2f;
  float normal_threshold = 2.0f;
  // One border colour for every object. SobelEdgeParams' default_border_color is used (no
  // per-pixel border texture): the functor requires a border texture to match the depth
  // texture's size, and a constant colour needs no texture reads at all.
  glm::vec4 border_color{0.0f, 0.0f, 0.0f, 1.0f};
};

class ScreenSpaceOutlineFeature final : public RendererFeature {
 public:
  explicit ScreenSpaceOutlineFeature(ScreenSpaceOutlineSettings settings = {});
  ~ScreenSpaceOutlineFeature() override;
  std::string name() const override { return "ScreenSpaceOutline"; }
  int event() const override { return settings_.event; }
  FeatureInputs required_inputs() const override { return {true, true, true}; }
  // Reads the colour copy, the depth and normals textures; writes the camera colour (blit pass
  // "blit ScreenSpaceOutline"). Throws Error when the pipeline did not produce its inputs.
  void record(RenderContext& context, const RenderingData& data) override;

 private:
  ScreenSpaceOutlineSettings settings_;
  std::unique_ptr<Shader> shader_;
  std::unique_ptr<RenderMaterial> material_;  // recorded by pointer: lives as long as the feature
};

}  // namespace ontile
