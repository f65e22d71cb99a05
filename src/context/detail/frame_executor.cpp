// Frame execution (see frame_executor.h).
#include "context/detail/frame_executor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "shaders_cpp/full_screen.h"
#include "util/error.h"
#include "util/worker_threads.h"

namespace ontile {
namespace {

// A blit's source: "_MainTex", clamped, without mipmaps.
PropertyBlock blit_source_properties(const RenderTargetRef& source) {
  PropertyBlock extra;
  extra.textures["_MainTex"] = TextureBinding{nullptr, source, SamplerDesc{}};
  extra.textures["_MainTex"].sampler.mipmap_mode = MipmapMode::None;
  extra.textures["_MainTex"].sampler.wrap_u = extra.textures["_MainTex"].sampler.wrap_v = WrapMode::ClampToEdge;
  return extra;
}

int thread_count(const ContextConfig& config) {
  const int threads = config.threads > 0 ? config.threads
                                         : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  allow_worker_threads(threads);  // 7 threads on 2 cores run 7 workers, without a TBB warning
  return threads;
}

}  // namespace

FrameExecutor::FrameExecutor(const ContextConfig& config, RenderTargetPool& pool)
    : config_(config), pool_(pool), arena_(thread_count(config)),
      memory_(make_memory_model(memory_config_of(config.tiler))) {
  frame_.threads = thread_count(config);
}

FrameReport FrameExecutor::run(const std::vector<Command>& commands) {
  const auto start = std::chrono::steady_clock::now();
  for (const Command& c : commands) std::visit(*this, c);
  if (pass_) {
    if (!pass_->implicit) throw Error("render pass '" + pass_->desc.name + "' was never ended");
    close_pass();
  }
  frame_.total_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return std::move(frame_);
}

Surface* FrameExecutor::resolve(const RenderTargetRef& ref, const char* what) {
  if (ref.surface) return ref.surface;
  const auto it = temporaries_.find(ref.temporary_id);
  if (it == temporaries_.end()) {
    throw Error(std::string(what) + ": temporary render target " + std::to_string(ref.temporary_id) +
                " was not allocated (get_temporary_rt) or was released");
  }
  return it->second;
}

std::shared_ptr<const Texture2D> FrameExecutor::texture_of(const TextureBinding& binding, bool texel_reads) {
  if (binding.texture) return binding.texture;
  Surface* s = resolve(binding.render_target, "texture binding");
  if (pass_) {
    for (const AttachmentDesc& a : pass_->desc.attachments) {
      if (a.surface == s || a.resolve_surface == s) {
        throw Error("render target '" + s->name() + "' is sampled while it is an attachment of pass '" +
                    pass_->desc.name + "' (use an input attachment)");
      }
    }
  }
  if (s->samples() != 1) {
    throw Error("render target '" + s->name() + "' is multisampled and cannot be sampled; resolve it first");
  }
  // One texture per surface and pass, so a surface is one texture region of the cache model
  // however often the pass binds it (and a new region in each pass, as before views existed).
  auto& texture = surface_textures_[s];
  if (texture) {
    textures_.push_back(texture);
    return texture;
  }
  if (Texture2D::samples_in_place(s->format()) || texel_reads) {
    // Sampled in place, no copy: surfaces change only while a pass executes (close_pass), and a
    // surface the open pass samples is not one of its attachments (checked above), so its bytes
    // stay as they are now until the pass's draws have run. A shader that only fetches texels
    // decodes each one once whatever the format (the view's addresses are the copy's: the same
    // texel bytes per pixel), so packed formats need no copy for it either; a later filtered
    // reader in the pass samples the same view (the same values: decode_pixel).
    texture = Texture2D::view_of_surface(s->width(), s->height(), s->format(),
                                         s->pixel_bytes(0, 0), s->name());
  } else {
    // Packed formats: decoded once, a row at a time straight into the texture's texels
    // (decode_pixels: the values Surface::read gives, on SIMD lanes), cheaper than decoding at
    // every texel read of the pass.
    const size_t row_floats = static_cast<size_t>(s->width()) * 4;
    std::vector<float> rgba(row_floats * s->height());
    static_assert(sizeof(glm::vec4) == 4 * sizeof(float) && alignof(glm::vec4) == alignof(float),
                  "a row of vec4 is a row of floats");
    for (int y = 0; y < s->height(); ++y) {
      decode_pixels(s->format(), s->pixel_bytes(0, y), s->width(),
                    reinterpret_cast<glm::vec4*>(rgba.data() + row_floats * y));
    }
    texture = Texture2D::from_surface_texels(s->width(), s->height(), std::move(rgba),
                                             bytes_per_pixel(s->format()), s->name());
  }
  textures_.push_back(texture);
  return texture;
}

SubpassDesc& FrameExecutor::current_subpass(const char* what) {
  if (!pass_) {
    throw Error(std::string(what) + " outside a render pass: call set_render_target or begin_render_pass first");
  }
  if (!pass_->in_subpass) throw Error(std::string(what) + " outside a subpass of pass '" + pass_->desc.name + "'");
  return pass_->desc.subpasses.back();
}

void FrameExecutor::close_pass() {
  OpenPass pass = std::move(*pass_);
  pass_.reset();
  // Inspection copies of what every tile held (the HTML report shows transient attachments).
  std::vector<std::unique_ptr<Surface>> captures;
  if (config_.pass_observer && config_.pass_observer->wants_tile_contents()) {
    for (const AttachmentDesc& a : pass.desc.attachments) {
      captures.push_back(std::make_unique<Surface>(a.name, a.format, pass.desc.width_px, pass.desc.height_px,
                                                   pass.desc.samples));
      pass.desc.capture_surfaces.push_back(captures.back().get());
    }
  }
  arena_.execute([&] {
    frame_.passes.push_back(execute_render_pass(pass.desc, config_.tiler, *memory_));
  });
  if (config_.pass_observer) {
    config_.pass_observer->pass_executed(frame_.passes.size() - 1, pass.desc, frame_.passes.back());
  }
  vertex_shaders_.clear();
  fragment_shaders_.clear();
  textures_.clear();
  surface_textures_.clear();  // the next pass samples surfaces as new texture regions
}

void FrameExecutor::add_draw(DrawCall draw) {
  current_subpass("draw").draws.push_back(draw);
  pass_->has_draws = true;
}

void FrameExecutor::operator()(const op::BeginRenderPass& c) {
  if (pass_ && !pass_->implicit) throw Error("begin_render_pass('" + c.name + "') inside another render pass");
  if (pass_) close_pass();
  OpenPass p;
  p.desc.name = c.name;
  p.desc.width_px = c.width_px;
  p.desc.height_px = c.height_px;
  p.desc.samples = c.samples;
  p.desc.attachments = c.attachments;
  p.desc.depth_index = c.depth_index;
  pass_ = std::move(p);
}

void FrameExecutor::operator()(const op::BeginSubpass& c) {
  if (!pass_ || pass_->implicit || pass_->in_subpass) throw Error("begin_subpass outside an explicit render pass");
  pass_->desc.subpasses.push_back({c.color_outputs, c.inputs, c.depth_read_only, {}});
  pass_->in_subpass = true;
}

void FrameExecutor::operator()(const op::EndSubpass&) { pass_->in_subpass = false; }

void FrameExecutor::operator()(const op::EndRenderPass&) { close_pass(); }

void FrameExecutor::operator()(const op::RawDraw& c) { add_draw(c.draw); }

void FrameExecutor::operator()(const op::SetRenderTarget& c) {
  if (pass_ && !pass_->implicit) throw Error("set_render_target inside render pass '" + pass_->desc.name + "'");
  if (pass_) close_pass();
  if (c.colors.empty() && !c.depth) throw Error("set_render_target without any target");
  OpenPass p;
  p.implicit = true;
  p.in_subpass = true;
  p.desc.name = c.name.empty() ? "pass " + std::to_string(implicit_pass_count_) : c.name;
  ++implicit_pass_count_;
  auto attach = [&](const TargetBinding& b, const char* role) {
    Surface* s = resolve(b.target, "set_render_target");
    if (p.desc.attachments.empty()) {
      p.desc.width_px = s->width();
      p.desc.height_px = s->height();
      p.desc.samples = s->samples();
    }
    AttachmentDesc a;
    a.name = s->name();
    a.format = s->format();
    a.load = b.load;
    a.store = b.store;
    a.clear_value = std::string(role) == "depth" ? glm::vec4(1.0f) : glm::vec4(0.0f);
    a.surface = s;
    p.desc.attachments.push_back(a);
  };
  SubpassDesc sub;
  for (const TargetBinding& b : c.colors) {
    attach(b, "color");
    sub.color_outputs.push_back(static_cast<int>(p.desc.attachments.size()) - 1);
  }
  if (c.depth) {
    attach(*c.depth, "depth");
    p.desc.depth_index = static_cast<int>(p.desc.attachments.size()) - 1;
  }
  p.desc.subpasses.push_back(std::move(sub));
  pass_ = std::move(p);
}

void FrameExecutor::operator()(const op::ClearRenderTarget& c) {
  if (!pass_ || !pass_->implicit) throw Error("clear_render_target needs a target set by set_render_target");
  RenderPassDesc& d = pass_->desc;
  if (!pass_->has_draws) {
    // Nothing drawn yet: a clear is a load action, free on a tile-based GPU.
    for (size_t a = 0; a < d.attachments.size(); ++a) {
      const bool is_depth = static_cast<int>(a) == d.depth_index;
      if ((is_depth && c.clear_depth) || (!is_depth && c.clear_color)) {
        d.attachments[a].load = LoadAction::Clear;
        d.attachments[a].clear_value = is_depth ? glm::vec4(c.depth) : c.color;
      }
    }
    return;
  }
  // After draws the clear costs fragments: a full-screen triangle writing the values.
  PassState state;
  state.cull = CullMode::None;
  state.depth_test = c.clear_depth;
  state.depth_compare = CompareOp::Always;
  state.depth_write = c.clear_depth;
  state.blend.write_mask = c.clear_color ? 0xF : 0x0;
  const int outputs = static_cast<int>(d.subpasses.back().color_outputs.size());
  add_full_screen_draw(std::make_unique<FullScreenVertexShader>(c.depth),
                       std::make_unique<ClearColorShader>(c.color, outputs), state);
}

void FrameExecutor::add_full_screen_draw(std::unique_ptr<VertexShader> vs,
                                         std::unique_ptr<FragmentShader> fs,
                                         const PassState& state) {
  DrawCall d;
  d.vertex_shader = vs.get();
  d.fragment_shader = fs.get();
  d.vertex_count = 3;
  d.indices = full_screen_indices();
  d.index_count = 3;
  d.raster.cull = state.cull;
  d.raster.depth_test = state.depth_test;
  d.raster.depth_write = state.depth_write;
  d.raster.depth_compare = state.depth_compare;
  d.blend = state.blend;
  vertex_shaders_.push_back(std::move(vs));
  fragment_shaders_.push_back(std::move(fs));
  add_draw(d);
}

void FrameExecutor::draw_with_pass(const MeshPrimitive* mesh, const glm::dmat4& world,
                                   const RenderMaterial& material, const ShaderPass& pass,
                                   uint32_t primitive_id_base, const PropertyBlock* extra) {
  current_subpass("draw");
  DrawContext ctx;
  ctx.mesh = mesh;
  ctx.world = world;
  ctx.camera = camera_;
  ctx.material = &material;
  ctx.properties = globals_;
  ctx.properties.merge_from(material.shader->defaults);
  ctx.properties.merge_from(material.properties);
  if (extra) ctx.properties.merge_from(*extra);
  ctx.target_width_px = pass_->desc.width_px;
  ctx.target_height_px = pass_->desc.height_px;
  ctx.resolve_texture = [this](const TextureBinding& b) { return texture_of(b); };
  ctx.resolve_texel_source = [this](const TextureBinding& b) { return texture_of(b, true); };
  DrawFunctors f = pass.factory(ctx);
  if (!f.vertex) throw Error("shader '" + material.shader->name() + "' pass '" + pass.name + "' built no vertex shader");
  const PassState state = material.state_for(pass);
  DrawCall d;
  d.vertex_shader = f.vertex.get();
  d.fragment_shader = f.fragment.get();
  d.vertex_count = mesh ? static_cast<uint32_t>(mesh->positions.size()) : 3;
  d.indices = mesh ? mesh->indices.data() : full_screen_indices();
  d.index_count = mesh ? static_cast<uint32_t>(mesh->indices.size()) : 3;
  d.raster.cull = state.cull;
  d.raster.depth_test = state.depth_test;
  d.raster.depth_write = state.depth_write;
  d.raster.depth_compare = state.depth_compare;
  d.blend = state.blend;
  d.primitive_id_base = primitive_id_base;
  d.input_vertex_bytes = f.input_vertex_bytes;
  vertex_shaders_.push_back(std::move(f.vertex));
  if (f.fragment) fragment_shaders_.push_back(std::move(f.fragment));
  add_draw(d);
}

void FrameExecutor::operator()(const op::DrawRenderers& c) {
  current_subpass("draw_renderers");
  const std::vector<Renderer>& all = *c.culling.renderers;
  camera_ = c.culling.camera;
  std::vector<uint32_t> list;
  for (uint32_t i : c.culling.visible) {
    const Renderer& r = all[i];
    const int queue = r.material->render_queue;
    if (queue < c.filtering.render_queue_range.lower || queue > c.filtering.render_queue_range.upper) continue;
    if (!((c.filtering.layer_mask >> (r.layer & 31)) & 1u)) continue;
    if (!(c.filtering.rendering_layer_mask & r.rendering_layer_mask)) continue;
    list.push_back(i);
  }
  // Sort keys: distance from the camera to the bounds centre; materials numbered in order of
  // first appearance so that ties never depend on addresses.
  std::map<const RenderMaterial*, uint32_t> material_order;
  std::vector<double> distance(all.size(), 0.0);
  double max_distance = 0.0;
  for (uint32_t i : list) {
    material_order.emplace(all[i].material, static_cast<uint32_t>(material_order.size()));
    distance[i] = glm::length(glm::dvec3(all[i].world_bounds.center()) - c.culling.camera.position);
    max_distance = std::max(max_distance, distance[i]);
  }
  auto bucket = [&](uint32_t i) {  // 64 front-to-back buckets, coarse enough to batch materials
    return max_distance > 0.0 ? static_cast<int>(distance[i] / max_distance * 63.0) : 0;
  };
  switch (c.drawing.sorting) {
    case SortingCriteria::None:
      break;
    case SortingCriteria::CommonOpaque:
      std::stable_sort(list.begin(), list.end(), [&](uint32_t a, uint32_t b) {
        const auto ka = std::tuple(all[a].material->render_queue, bucket(a), material_order[all[a].material]);
        const auto kb = std::tuple(all[b].material->render_queue, bucket(b), material_order[all[b].material]);
        return ka < kb;
      });
      break;
    case SortingCriteria::CommonTransparent:
      std::stable_sort(list.begin(), list.end(), [&](uint32_t a, uint32_t b) {
        if (all[a].material->render_queue != all[b].material->render_queue) {
          return all[a].material->render_queue < all[b].material->render_queue;
        }
        return distance[a] > distance[b];
      });
      break;
  }
  for (uint32_t i : list) {
    const Renderer& r = all[i];
    for (const std::string& light_mode : c.drawing.light_modes) {
      const ShaderPass* pass = r.material->shader->find_light_mode(light_mode);
      if (pass) draw_with_pass(r.mesh, r.world, *r.material, *pass, r.primitive_id_base);
    }
  }
}

void FrameExecutor::operator()(const op::DrawMesh& c) {
  const ShaderPass* pass = c.material->shader->find_pass(c.pass_name);
  if (!pass) throw Error("draw_mesh: shader '" + c.material->shader->name() + "' has no pass '" + c.pass_name + "'");
  draw_with_pass(c.mesh, c.world, *c.material, *pass, c.primitive_id_base);
}

void FrameExecutor::operator()(const op::DrawSkybox& c) {
  current_subpass("draw_skybox");
  const glm::dmat4 inverse_vp = glm::inverse(c.camera.view_projection);
  PassState state;
  state.cull = CullMode::None;
  state.depth_write = false;
  state.depth_compare = CompareOp::LessEqual;  // only where nothing nearer was drawn
  auto sky = std::make_unique<GradientSkyShader>(
      glm::vec3(globals_.get_vector("_SkyZenithColor", glm::vec4(0.18f, 0.32f, 0.62f, 1.0f))),
      glm::vec3(globals_.get_vector("_SkyHorizonColor", glm::vec4(0.62f, 0.70f, 0.80f, 1.0f))),
      glm::vec3(globals_.get_vector("_SkyGroundColor", glm::vec4(0.25f, 0.23f, 0.21f, 1.0f))));
  add_full_screen_draw(std::make_unique<FullScreenVertexShader>(1.0f, &inverse_vp), std::move(sky), state);
}

void FrameExecutor::operator()(const op::DrawFullScreen& c) {
  const ShaderPass* pass = c.material->shader->find_pass(c.pass_name);
  if (!pass) {
    throw Error("draw_full_screen: shader '" + c.material->shader->name() + "' has no pass '" + c.pass_name + "'");
  }
  if (!c.main_texture.valid()) return draw_with_pass(nullptr, glm::dmat4(1.0), *c.material, *pass, 0);
  const PropertyBlock extra = blit_source_properties(c.main_texture);
  draw_with_pass(nullptr, glm::dmat4(1.0), *c.material, *pass, 0, &extra);
}

void FrameExecutor::operator()(const op::Blit& c) {
  if (pass_ && !pass_->implicit) throw Error("blit inside render pass '" + pass_->desc.name + "'");
  if (pass_) close_pass();
  const ShaderPass* pass = c.material ? c.material->shader->find_pass(c.pass_name) : nullptr;
  if (!pass) throw Error("blit: material has no pass '" + c.pass_name + "'");
  resolve(c.source, "blit source");
  op::SetRenderTarget target;
  target.name = "blit " + c.material->name;
  target.colors.push_back({c.destination, LoadAction::DontCare, StoreAction::Store});
  (*this)(target);
  const PropertyBlock extra = blit_source_properties(c.source);
  draw_with_pass(nullptr, glm::dmat4(1.0), *c.material, *pass, 0, &extra);
  close_pass();
}

void FrameExecutor::operator()(const op::SetViewProjection& c) {
  camera_.view = c.view;
  camera_.projection = c.projection;
  camera_.view_projection = c.projection * c.view;
  camera_.position = glm::dvec3(glm::inverse(c.view)[3]);
}

void FrameExecutor::operator()(const op::GetTemporaryRT& c) {
  if (temporaries_.count(c.id)) throw Error("get_temporary_rt: id " + std::to_string(c.id) + " is already allocated");
  temporaries_[c.id] = pool_.acquire(c.desc, "temporary " + std::to_string(c.id));
}

void FrameExecutor::operator()(const op::ReleaseTemporaryRT& c) {
  const auto it = temporaries_.find(c.id);
  if (it == temporaries_.end()) throw Error("release_temporary_rt: id " + std::to_string(c.id) + " is not allocated");
  // A target the open pass still renders to: run that pass before the surface is reused.
  if (pass_ && std::any_of(pass_->desc.attachments.begin(), pass_->desc.attachments.end(),
                           [&](const AttachmentDesc& a) { return a.surface == it->second; })) {
    close_pass();
  }
  pool_.release(it->second);
  temporaries_.erase(it);
}

}  // namespace ontile
