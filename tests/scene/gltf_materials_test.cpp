// glTF loader materials on a file written by the test: factors, alpha, extras JSON, emissive
// strength, texture colour spaces and cache, sampler mapping, 1/2/3/4-channel and 16-bit PNGs.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_test_files.h"
#include "scene/gltf_loader.h"

namespace ontile {
namespace {

using nlohmann::json;

json png_image(int width, int height, int color_type, int bit_depth,
               const std::vector<uint16_t>& samples) {
  return {{"uri", "data:image/png;base64," +
                      test::base64(test::make_png(width, height, color_type, bit_depth, samples))}};
}

// A linear (Unorm8) texel back as its 8-bit value.
glm::ivec4 texel8(const Texture2D& texture, int x, int y) {
  const glm::vec4 v = texture.fetch(0, x, y);
  return glm::ivec4(std::lround(v.x * 255.0f), std::lround(v.y * 255.0f), std::lround(v.z * 255.0f),
                    std::lround(v.w * 255.0f));
}

class GltfMaterials : public ::testing::Test {
 protected:
  void SetUp() override {
    test::GltfBuilder b;
    const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    b.add_mesh(json::array({{{"attributes", {{"POSITION", pos}}}, {"material", 0}}}));
    b.add_node({{"mesh", 0}});
    b.json["scenes"] = json::array({{{"nodes", {0}}}});
    b.json["images"] = json::array({
        png_image(2, 1, 0, 8, {0, 200}),                   // grey
        png_image(1, 1, 4, 8, {100, 50}),                  // grey + alpha
        png_image(1, 1, 2, 8, {10, 20, 30}),               // RGB
        png_image(1, 1, 6, 16, {0, 65535, 33024, 33025}),  // RGBA, 16 bits
    });
    b.json["samplers"] = json::array({
        {{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33648}},
        {{"magFilter", 9729}, {"minFilter", 9985}},
        {{"minFilter", 9984}},
        {{"minFilter", 9729}, {"wrapS", 10497}},
    });
    b.json["textures"] = json::array({{{"source", 0}, {"sampler", 0}},
                                      {{"source", 1}, {"sampler", 1}},
                                      {{"source", 2}, {"sampler", 2}},
                                      {{"source", 3}, {"sampler", 3}},
                                      {{"source", 0}}});
    b.json["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    b.json["materials"] = json::array({
        {{"name", "first"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.5, 0.25, 1, 0.75}},
           {"metallicFactor", 0.125},
           {"roughnessFactor", 0.375},
           {"baseColorTexture", {{"index", 4}}},
           {"metallicRoughnessTexture", {{"index", 0}}}}},
         {"normalTexture", {{"index", 0}, {"scale", 0.5}, {"texCoord", 1}}},
         {"emissiveTexture", {{"index", 0}}},
         {"emissiveFactor", {1, 0.5, 0}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}},
         {"alphaMode", "MASK"},
         {"alphaCutoff", 0.25},
         {"doubleSided", true},
         {"extras",
          {{"ontile",
            {{"toon_bands", 3}, {"outline", true}, {"name", "x"}, {"w", 0.5}, {"list", {1, 2}}}}}}},
        {{"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", 1}}}}}},
        {{"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", 2}}}}},
         {"alphaMode", "BLEND"}},
        {{"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", 3}}}}}},
    });
    scene_ = load_gltf(b.write(test::gltf_test_dir(), "materials"));
  }
  Scene scene_;
};

TEST_F(GltfMaterials, FactorsAlphaAndExtras) {
  ASSERT_EQ(scene_.materials.size(), 4u);
  const Material& m = scene_.materials[0];
  EXPECT_EQ(m.name, "first");
  EXPECT_EQ(m.base_color_factor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
  EXPECT_EQ(m.metallic_factor, 0.125f);
  EXPECT_EQ(m.roughness_factor, 0.375f);
  EXPECT_EQ(m.normal_scale, 0.5f);
  EXPECT_EQ(m.emissive_factor, glm::vec3(4.0f, 2.0f, 0.0f));  // times emissiveStrength 4
  EXPECT_EQ(m.alpha_mode, AlphaMode::Mask);
  EXPECT_EQ(m.alpha_cutoff, 0.25f);
  EXPECT_TRUE(m.double_sided);
  EXPECT_EQ(m.extras_json,
            R"({"ontile":{"list":[1,2],"name":"x","outline":true,"toon_bands":3,"w":0.5}})");
  const Material& plain = scene_.materials[1];
  EXPECT_EQ(plain.base_color_factor, glm::vec4(1.0f));
  EXPECT_EQ(plain.metallic_factor, 1.0f);
  EXPECT_EQ(plain.roughness_factor, 1.0f);
  EXPECT_EQ(plain.emissive_factor, glm::vec3(0.0f));
  EXPECT_EQ(plain.alpha_mode, AlphaMode::Opaque);
  EXPECT_FALSE(plain.double_sided);
  EXPECT_EQ(plain.extras_json, "");
  EXPECT_EQ(plain.base_color_texture.texture, nullptr);
  EXPECT_EQ(scene_.materials[2].alpha_mode, AlphaMode::Blend);
  EXPECT_EQ(scene_.meshes.at(0).primitives.at(0).material, 0);
}

TEST_F(GltfMaterials, ColourSpacesAndOneTexturePerImageAndSpace) {
  const Material& m = scene_.materials[0];
  ASSERT_NE(m.base_color_texture.texture, nullptr);
  EXPECT_EQ(m.base_color_texture.texture->encoding(), TexelEncoding::Srgb8);
  EXPECT_EQ(m.emissive_texture.texture->encoding(), TexelEncoding::Srgb8);
  EXPECT_EQ(m.metallic_roughness_texture.texture->encoding(), TexelEncoding::Unorm8);
  EXPECT_EQ(m.normal_texture.texture->encoding(), TexelEncoding::Unorm8);
  // Image 0 appears through textures 0 and 4: once as sRGB, once as linear.
  EXPECT_EQ(m.base_color_texture.texture, m.emissive_texture.texture);
  EXPECT_EQ(m.metallic_roughness_texture.texture, m.normal_texture.texture);
  EXPECT_NE(m.base_color_texture.texture, m.normal_texture.texture);
  EXPECT_EQ(m.normal_texture.uv_set, 1);
  EXPECT_EQ(m.base_color_texture.uv_set, 0);
}

TEST_F(GltfMaterials, ImagesOfEveryChannelCountAndDepthBecomeRgba8) {
  const Texture2D& grey = *scene_.materials[0].metallic_roughness_texture.texture;
  ASSERT_EQ(grey.width(), 2);
  ASSERT_EQ(grey.height(), 1);
  EXPECT_EQ(texel8(grey, 0, 0), glm::ivec4(0, 0, 0, 255));
  EXPECT_EQ(texel8(grey, 1, 0), glm::ivec4(200, 200, 200, 255));
  EXPECT_EQ(texel8(*scene_.materials[1].metallic_roughness_texture.texture, 0, 0),
            glm::ivec4(100, 100, 100, 50));
  EXPECT_EQ(texel8(*scene_.materials[2].metallic_roughness_texture.texture, 0, 0),
            glm::ivec4(10, 20, 30, 255));
  // 16 bits round to nearest: 33024 / 257 = 128.498 -> 128, 33025 / 257 = 128.502 -> 129.
  EXPECT_EQ(texel8(*scene_.materials[3].metallic_roughness_texture.texture, 0, 0),
            glm::ivec4(0, 255, 128, 129));
}

TEST_F(GltfMaterials, SamplersMapToFilterAndWrapModes) {
  const SamplerDesc& s0 = scene_.materials[0].metallic_roughness_texture.sampler;
  EXPECT_EQ(s0.mag_filter, FilterMode::Nearest);
  EXPECT_EQ(s0.min_filter, FilterMode::Nearest);
  EXPECT_EQ(s0.mipmap_mode, MipmapMode::None);
  EXPECT_EQ(s0.wrap_u, WrapMode::ClampToEdge);
  EXPECT_EQ(s0.wrap_v, WrapMode::MirroredRepeat);
  const SamplerDesc& s1 = scene_.materials[1].metallic_roughness_texture.sampler;
  EXPECT_EQ(s1.mag_filter, FilterMode::Linear);
  EXPECT_EQ(s1.min_filter, FilterMode::Linear);
  EXPECT_EQ(s1.mipmap_mode, MipmapMode::Nearest);
  const SamplerDesc& s2 = scene_.materials[2].metallic_roughness_texture.sampler;
  EXPECT_EQ(s2.mag_filter, FilterMode::Linear);  // undefined: linear
  EXPECT_EQ(s2.min_filter, FilterMode::Nearest);
  EXPECT_EQ(s2.mipmap_mode, MipmapMode::Nearest);
  const SamplerDesc& s3 = scene_.materials[3].metallic_roughness_texture.sampler;
  EXPECT_EQ(s3.min_filter, FilterMode::Linear);
  EXPECT_EQ(s3.mipmap_mode, MipmapMode::None);
  EXPECT_EQ(s3.wrap_u, WrapMode::Repeat);
  // Texture 4 has no sampler: linear, trilinear, repeat.
  const SamplerDesc& none = scene_.materials[0].base_color_texture.sampler;
  EXPECT_EQ(none.mag_filter, FilterMode::Linear);
  EXPECT_EQ(none.min_filter, FilterMode::Linear);
  EXPECT_EQ(none.mipmap_mode, MipmapMode::Linear);
  EXPECT_EQ(none.wrap_u, WrapMode::Repeat);
  EXPECT_EQ(none.wrap_v, WrapMode::Repeat);
}

}  // namespace
}  // namespace ontile
