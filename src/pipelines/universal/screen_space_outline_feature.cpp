// The ScreenSpaceOutline renderer feature (see screen_space_outline_feature.h).
#include "pipelines/universal/screen_space_outline_feature.h"

#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/toon/sobel_edge_shader.h"
#include "util/error.h"

namespace ontile {
namespace {

DrawFunctors sobel_functors(const DrawContext& ctx) {
  const auto color = ctx.texel_source("_MainTex");
  const auto depth = ctx.texel_source("_CameraDepthTexture");
  const auto normals = ctx.texel_source("_CameraNormalsTexture");
  SobelEdgeParams p;
  p.color = color.get();
  p.depth = depth.get();
  p.normal = normals.get();
  p.depth_linearization = DepthLinearization::from_projection(ctx.camera.projection);
  p.normal_encoding = NormalEncoding::Unorm;
  p.default_border_color = ctx.properties.get_vector("_BorderColor", glm::vec4(0, 0, 0, 1));
  p.thickness_px = ctx.properties.get_float("_ThicknessPx", 1.0f);
  p.depth_threshold = ctx.properties.get_float("_DepthThreshold", 0.2f);
  p.normal_threshold = ctx.properties.get_float("_NormalThreshold", 2.0f);
  DrawFunctors f;
  f.vertex = std::make_unique<FullScreenVertexShader>();
  f.fragment = std::make_unique<SobelEdgeShader>(p);
  return f;
}

}  // namespace

ScreenSpaceOutlineFeature::ScreenSpaceOutlineFeature(ScreenSpaceOutlineSettings settings)
    : settings_(settings), shader_(std::make_unique<Shader>("Hidden/ScreenSpaceOutline")) {
  PassState state;
  state.cull = CullMode::None;
  state.depth_test = false;
  state.depth_write = false;
  shader_->add_pass({"ScreenSpaceOutline", "", state, sobel_functors});
  material_ = std::make_unique<RenderMaterial>("ScreenSpaceOutline", shader_.get());
  material_->properties.vectors["_BorderColor"] = settings_.border_color;
  material_->properties.floats["_ThicknessPx"] = settings_.thickness_px;
  material_->properties.floats["_DepthThreshold"] = settings_.depth_threshold;
  material_->properties.floats["_NormalThreshold"] = settings_.normal_threshold;
}

ScreenSpaceOutlineFeature::~ScreenSpaceOutlineFeature() = default;

void ScreenSpaceOutlineFeature::record(RenderContext& context, const RenderingData& data) {
  if (!data.camera_color_copy.valid() || !data.camera_depth.valid() || !data.camera_normals.valid()) {
    throw Error("ScreenSpaceOutline: the pipeline did not provide the colour copy, depth and normals "
                "it requires (event " + std::to_string(settings_.event) + ")");
  }
  SamplerDesc texel_exact;
  texel_exact.mag_filter = texel_exact.min_filter = FilterMode::Nearest;
  texel_exact.mipmap_mode = MipmapMode::None;
  texel_exact.wrap_u = texel_exact.wrap_v = WrapMode::ClampToEdge;
  material_->properties.textures["_CameraDepthTexture"] = {nullptr, data.camera_depth, texel_exact};
  material_->properties.textures["_CameraNormalsTexture"] = {nullptr, data.camera_normals, texel_exact};
  // The functor linearises depth with the camera's projection (URP sets the camera matrices
  // before a feature's full-screen pass the same way).
  context.set_view_projection(data.camera.view, data.camera.projection);
  context.blit(data.camera_color_copy, data.camera_color, material_.get(), "ScreenSpaceOutline");
}

}  // namespace ontile
