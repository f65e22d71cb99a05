// glTF 2.0 materials (pbrMetallicRoughness, normal, emissive, alpha, extras) and their
// textures: sampler mapping and image conversion to RGBA8, each (image, colour space) once.
#include <tiny_gltf.h>

#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "scene/gltf_internal.h"

namespace ontile::gltf {
namespace {

nlohmann::json value_to_json(const tinygltf::Value& value) {
  switch (value.Type()) {
    case tinygltf::BOOL_TYPE:
      return value.Get<bool>();
    case tinygltf::INT_TYPE:
      return value.Get<int>();
    case tinygltf::REAL_TYPE:
      return value.Get<double>();
    case tinygltf::STRING_TYPE:
      return value.Get<std::string>();
    case tinygltf::BINARY_TYPE:
      return value.Get<std::vector<unsigned char>>();
    case tinygltf::ARRAY_TYPE: {
      nlohmann::json array = nlohmann::json::array();
      for (const tinygltf::Value& item : value.Get<tinygltf::Value::Array>()) {
        array.push_back(value_to_json(item));
      }
      return array;
    }
    case tinygltf::OBJECT_TYPE: {
      nlohmann::json object = nlohmann::json::object();
      for (const auto& [key, item] : value.Get<tinygltf::Value::Object>()) {
        object[key] = value_to_json(item);
      }
      return object;
    }
    default:
      return nullptr;
  }
}

WrapMode wrap_mode(const LoadContext& context, int sampler_index, int gl_wrap) {
  switch (gl_wrap) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT:
      return WrapMode::Repeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
      return WrapMode::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
      return WrapMode::MirroredRepeat;
  }
  throw_error(context, "sampler " + std::to_string(sampler_index) + " has invalid wrap mode " +
                           std::to_string(gl_wrap));
}

// glTF samplers use the OpenGL enums (spec 5.26). An undefined filter is up to the client:
// ontile picks linear with trilinear mipmapping.
SamplerDesc sampler_desc(const LoadContext& context, int sampler_index) {
  SamplerDesc desc;
  if (sampler_index < 0) return desc;
  if (static_cast<size_t>(sampler_index) >= context.model.samplers.size()) {
    throw_error(context, "sampler " + std::to_string(sampler_index) + " does not exist");
  }
  const tinygltf::Sampler& sampler = context.model.samplers[static_cast<size_t>(sampler_index)];
  desc.wrap_u = wrap_mode(context, sampler_index, sampler.wrapS);
  desc.wrap_v = wrap_mode(context, sampler_index, sampler.wrapT);
  switch (sampler.magFilter) {
    case -1:
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
      desc.mag_filter = FilterMode::Linear;
      break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
      desc.mag_filter = FilterMode::Nearest;
      break;
    default:
      throw_error(context, "sampler " + std::to_string(sampler_index) + " has invalid magFilter " +
                               std::to_string(sampler.magFilter));
  }
  const std::map<int, std::pair<FilterMode, MipmapMode>> min_filters = {
      {-1, {FilterMode::Linear, MipmapMode::Linear}},
      {TINYGLTF_TEXTURE_FILTER_NEAREST, {FilterMode::Nearest, MipmapMode::None}},
      {TINYGLTF_TEXTURE_FILTER_LINEAR, {FilterMode::Linear, MipmapMode::None}},
      {TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST, {FilterMode::Nearest, MipmapMode::Nearest}},
      {TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST, {FilterMode::Linear, MipmapMode::Nearest}},
      {TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR, {FilterMode::Nearest, MipmapMode::Linear}},
      {TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR, {FilterMode::Linear, MipmapMode::Linear}},
  };
  const auto min_filter = min_filters.find(sampler.minFilter);
  if (min_filter == min_filters.end()) {
    throw_error(context, "sampler " + std::to_string(sampler_index) + " has invalid minFilter " +
                             std::to_string(sampler.minFilter));
  }
  desc.min_filter = min_filter->second.first;
  desc.mipmap_mode = min_filter->second.second;
  return desc;
}

// tinygltf's stb_image path yields 1-4 channels of 8 or 16 bits (16-bit little-endian).
// Grey expands to RGB, missing alpha is opaque, 16-bit rounds to nearest: (v * 255 + 32767) /
// 65535.
std::vector<uint8_t> to_rgba8(const LoadContext& context, int image_index,
                              const tinygltf::Image& image) {
  const std::string where = "image " + std::to_string(image_index) +
                            (image.uri.empty() ? std::string() : " ('" + image.uri + "')");
  const int channels = image.component;
  const int bytes_per_channel = image.bits / 8;
  if (image.width < 1 || image.height < 1 || channels < 1 || channels > 4 ||
      (image.bits != 8 && image.bits != 16)) {
    throw_error(context, where + " has unsupported pixel format (" + std::to_string(image.width) +
                             "x" + std::to_string(image.height) + ", " + std::to_string(channels) +
                             " channels, " + std::to_string(image.bits) + " bits)");
  }
  const size_t pixel_count = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  if (image.image.size() != pixel_count * static_cast<size_t>(channels * bytes_per_channel)) {
    throw_error(
        context,
        where + " has " + std::to_string(image.image.size()) + " bytes of pixel data, expected " +
            std::to_string(pixel_count * static_cast<size_t>(channels * bytes_per_channel)));
  }
  const uint8_t* data = image.image.data();
  auto channel = [&](size_t pixel, int c) -> uint8_t {
    const size_t offset = (pixel * static_cast<size_t>(channels) + static_cast<size_t>(c)) *
                          static_cast<size_t>(bytes_per_channel);
    if (bytes_per_channel == 1) return data[offset];
    const uint32_t v = uint32_t{data[offset]} | (uint32_t{data[offset + 1]} << 8);
    return static_cast<uint8_t>((v * 255u + 32767u) / 65535u);
  };
  std::vector<uint8_t> rgba(pixel_count * 4);
  for (size_t p = 0; p < pixel_count; ++p) {
    uint8_t* out = rgba.data() + 4 * p;
    if (channels <= 2) {
      out[0] = out[1] = out[2] = channel(p, 0);
      out[3] = channels == 2 ? channel(p, 1) : 255;
    } else {
      out[0] = channel(p, 0);
      out[1] = channel(p, 1);
      out[2] = channel(p, 2);
      out[3] = channels == 4 ? channel(p, 3) : 255;
    }
  }
  return rgba;
}

class TextureBuilder {
 public:
  explicit TextureBuilder(const LoadContext& context) : context_(context) {}

  TextureSlot slot(int material_index, int texture_index, int tex_coord, bool srgb) {
    TextureSlot slot;
    if (texture_index < 0) return slot;
    const auto& model = context_.model;
    if (static_cast<size_t>(texture_index) >= model.textures.size()) {
      throw_error(context_, "material " + std::to_string(material_index) + " refers to texture " +
                                std::to_string(texture_index) + ", which does not exist");
    }
    const tinygltf::Texture& texture = model.textures[static_cast<size_t>(texture_index)];
    if (texture.source < 0) {
      // Only possible with an image extension the loader does not know (not required, or the
      // load would have failed): the slot stays unused.
      context_.stats.warnings.push_back("texture " + std::to_string(texture_index) +
                                        " has no image source; ignored");
      return slot;
    }
    if (static_cast<size_t>(texture.source) >= model.images.size()) {
      throw_error(context_, "texture " + std::to_string(texture_index) + " refers to image " +
                                std::to_string(texture.source) + ", which does not exist");
    }
    slot.texture = build(texture.source, srgb);
    slot.sampler = sampler_desc(context_, texture.sampler);
    slot.uv_set = tex_coord;
    return slot;
  }

 private:
  std::shared_ptr<const Texture2D> build(int image_index, bool srgb) {
    const auto key = std::make_pair(image_index, srgb);
    const auto cached = cache_.find(key);
    if (cached != cache_.end()) return cached->second;
    const tinygltf::Image& image = context_.model.images[static_cast<size_t>(image_index)];
    std::string name = !image.name.empty()  ? image.name
                       : !image.uri.empty() ? image.uri
                                            : "image " + std::to_string(image_index);
    auto texture = Texture2D::from_rgba8(image.width, image.height, to_rgba8(context_, image_index, image),
                                         srgb, std::move(name), context_.options.texture_compression);
    cache_.emplace(key, texture);
    return texture;
  }

  const LoadContext& context_;
  std::map<std::pair<int, bool>, std::shared_ptr<const Texture2D>> cache_;
};

AlphaMode alpha_mode(const LoadContext& context, int material_index, const std::string& mode) {
  if (mode == "OPAQUE" || mode.empty()) return AlphaMode::Opaque;
  if (mode == "MASK") return AlphaMode::Mask;
  if (mode == "BLEND") return AlphaMode::Blend;
  throw_error(context, "material " + std::to_string(material_index) + " has invalid alphaMode '" +
                           mode + "'");
}

}  // namespace

std::vector<Material> convert_materials(const LoadContext& context) {
  TextureBuilder textures(context);
  std::vector<Material> materials;
  const auto& sources = context.model.materials;
  for (size_t m = 0; m < sources.size(); ++m) {
    const tinygltf::Material& source = sources[m];
    const int index = static_cast<int>(m);
    const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
    Material material;
    material.name = source.name;
    if (pbr.baseColorFactor.size() == 4) {
      material.base_color_factor = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1],
                                             pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
    }
    // Colour textures (base colour, emissive) are sRGB, data textures linear (spec 3.9.2).
    material.base_color_texture =
        textures.slot(index, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, true);
    material.metallic_factor = static_cast<float>(pbr.metallicFactor);
    material.roughness_factor = static_cast<float>(pbr.roughnessFactor);
    material.metallic_roughness_texture = textures.slot(
        index, pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord, false);
    material.normal_texture =
        textures.slot(index, source.normalTexture.index, source.normalTexture.texCoord, false);
    material.normal_scale = static_cast<float>(source.normalTexture.scale);
    if (source.emissiveFactor.size() == 3) {
      material.emissive_factor =
          glm::vec3(source.emissiveFactor[0], source.emissiveFactor[1], source.emissiveFactor[2]);
    }
    // KHR_materials_emissive_strength scales the emissive factor.
    const auto strength = source.extensions.find("KHR_materials_emissive_strength");
    if (strength != source.extensions.end() && strength->second.Has("emissiveStrength")) {
      material.emissive_factor *=
          static_cast<float>(strength->second.Get("emissiveStrength").GetNumberAsDouble());
    }
    material.emissive_texture =
        textures.slot(index, source.emissiveTexture.index, source.emissiveTexture.texCoord, true);
    material.alpha_mode = alpha_mode(context, index, source.alphaMode);
    material.alpha_cutoff = static_cast<float>(source.alphaCutoff);
    material.double_sided = source.doubleSided;
    if (source.extras.Type() != tinygltf::NULL_TYPE) {
      material.extras_json = value_to_json(source.extras).dump();
    }
    materials.push_back(std::move(material));
  }
  return materials;
}

}  // namespace ontile::gltf
