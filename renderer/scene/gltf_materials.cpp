#include "scene/gltf_materials.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "materials/metallic_roughness.h"
#include "util/printable.h"

namespace strata {
namespace {

bool isFiniteFloat(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

Material metallicRoughnessMaterial(const std::string& name, const glm::vec3& baseColor, float metallic,
                                   float roughness, const glm::vec3& emission) {
    Material material;
    material.name = name;
    const LayeredReflectance r = fromMetallicRoughness(baseColor, metallic);
    material.diffuse = r.diffuse;
    material.specular = r.specular;
    material.roughness = roughness;
    material.emission = emission;
    return material;
}

// The texture a material's texture reference names, decoded; null (with a warning) when the
// reference, its image or the image's bytes cannot be used.
std::shared_ptr<const Texture> textureOf(GltfModel& gltf, SceneTextures& textures, const std::string& where,
                                         int textureIndex, int texCoord, const tinygltf::ExtensionMap& extensions,
                                         TextureEncoding encoding) {
    if (textureIndex < 0) return nullptr;
    const tinygltf::Texture& texture = gltf.element(gltf.model.textures, textureIndex, where + ": texture");
    if (const auto transform = extensions.find("KHR_texture_transform"); transform != extensions.end()) {
        const tinygltf::Value& set = transform->second.Get("texCoord");
        if (set.IsInt()) texCoord = set.GetNumberAsInt();  // the extension's set overrides the reference's
    }
    if (texCoord != 0) {
        gltf.warnOnce(where + " uses TEXCOORD_" + std::to_string(texCoord) + ", which Strata does not read; ignored");
        return nullptr;
    }
    if (texture.source < 0) {
        gltf.warnOnce(where + ": texture " + std::to_string(textureIndex) + " has no image it can read; ignored");
        return nullptr;
    }
    const tinygltf::Image& image = gltf.element(gltf.model.images, texture.source, where + ": image");
    const auto source = static_cast<size_t>(texture.source);
    const std::string name = image.uri.empty() || image.uri.rfind("data:", 0) == 0
                                 ? "image " + std::to_string(source)
                                 : image.uri;
    if (source >= gltf.images.size() || gltf.images[source].empty()) {
        gltf.warnOnce(where + ": image " + quote(name) + " is missing; using the factor alone");
        return nullptr;
    }
    return textures.bytes(name, gltf.images[source], encoding, gltf.path + ": " + where);
}

// The numbers of `name` in a KHR_texture_transform object, else `otherwise`.
template <size_t N>
std::array<double, N> transformNumbers(GltfModel& gltf, const std::string& where, const tinygltf::Value& transform,
                                       const char* name, std::array<double, N> otherwise) {
    if (!transform.Has(name)) return otherwise;
    const tinygltf::Value& value = transform.Get(name);
    std::array<double, N> numbers{};
    const bool array = N > 1 && value.IsArray() && value.ArrayLen() == N;
    for (size_t i = 0; i < N; ++i) {
        const tinygltf::Value& number = array ? value.Get(static_cast<int>(i)) : value;
        if (!(N == 1 || array) || !number.IsNumber() || !std::isfinite(number.GetNumberAsDouble())) {
            gltf.fail(where + ": KHR_texture_transform " + name + " needs " + std::to_string(N) + " finite number" +
                      (N > 1 ? "s" : ""));
        }
        numbers[i] = number.GetNumberAsDouble();
    }
    return numbers;
}

// KHR_texture_transform, "Overview": T * R * S as column-major 3x3 matrices on (u, v, 1).
glm::dmat3 transformOf(GltfModel& gltf, const std::string& where, const tinygltf::ExtensionMap& extensions) {
    const auto it = extensions.find("KHR_texture_transform");
    if (it == extensions.end()) return glm::dmat3(1.0);
    const auto offset = transformNumbers<2>(gltf, where, it->second, "offset", {0.0, 0.0});
    const double rotation = transformNumbers<1>(gltf, where, it->second, "rotation", {0.0})[0];
    const auto scale = transformNumbers<2>(gltf, where, it->second, "scale", {1.0, 1.0});
    const double c = std::cos(rotation);
    const double s = std::sin(rotation);
    const glm::dmat3 translate(1, 0, 0, 0, 1, 0, offset[0], offset[1], 1);
    const glm::dmat3 rotate(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::dmat3 stretch(scale[0], 0, 0, 0, scale[1], 0, 0, 0, 1);
    return translate * rotate * stretch;
}

}  // namespace

glm::dmat3 gltfTextureTransform(GltfModel& gltf, size_t index) {
    const tinygltf::Material& m = gltf.model.materials[index];
    const std::string name = "material '" + m.name + "' (" + std::to_string(index) + ")";
    const auto& pbr = m.pbrMetallicRoughness;
    const std::array<std::pair<const char*, std::pair<int, const tinygltf::ExtensionMap*>>, 4> slots{{
        {"baseColorTexture", {pbr.baseColorTexture.index, &pbr.baseColorTexture.extensions}},
        {"metallicRoughnessTexture", {pbr.metallicRoughnessTexture.index, &pbr.metallicRoughnessTexture.extensions}},
        {"emissiveTexture", {m.emissiveTexture.index, &m.emissiveTexture.extensions}},
        {"normalTexture", {m.normalTexture.index, &m.normalTexture.extensions}},
    }};
    const char* first = nullptr;
    glm::dmat3 transform(1.0);
    for (const auto& [slot, reference] : slots) {
        if (reference.first < 0) continue;
        const glm::dmat3 own = transformOf(gltf, name + " " + slot, *reference.second);
        if (!first) {
            first = slot;
            transform = own;
        } else if (own != transform) {
            gltf.warnOnce(name + ": " + slot + "'s KHR_texture_transform differs from " + first +
                          "'s, which Strata applies to all its textures (one UV set per primitive)");
        }
    }
    return transform;
}

Material gltfDefaultMaterial() {
    return metallicRoughnessMaterial("(glTF default)", glm::vec3(1.0f), 1.0f, 1.0f, glm::vec3(0.0f));
}

Material gltfMaterial(GltfModel& gltf, SceneTextures& textures, size_t index) {
    const tinygltf::Material& m = gltf.model.materials[index];
    const std::string name = "material " + quote(m.name) + " (" + std::to_string(index) + ")";
    const auto& pbr = m.pbrMetallicRoughness;
    const auto inUnitRange = [](double v) { return v >= 0.0 && v <= 1.0; };
    if (pbr.baseColorFactor.size() != 4 ||
        !std::all_of(pbr.baseColorFactor.begin(), pbr.baseColorFactor.end(), inUnitRange)) {
        gltf.fail(name + ": baseColorFactor needs 4 numbers in 0..1");
    }
    if (!inUnitRange(pbr.metallicFactor)) gltf.fail(name + ": metallicFactor outside 0..1");
    if (!inUnitRange(pbr.roughnessFactor)) gltf.fail(name + ": roughnessFactor outside 0..1");
    if (m.emissiveFactor.size() != 3 || !std::all_of(m.emissiveFactor.begin(), m.emissiveFactor.end(), inUnitRange)) {
        gltf.fail(name + ": emissiveFactor needs 3 numbers in 0..1");
    }
    double strength = 1.0;
    if (const auto it = m.extensions.find("KHR_materials_emissive_strength"); it != m.extensions.end()) {
        const tinygltf::Value& value = it->second.Get("emissiveStrength");
        if (value.IsNumber()) strength = value.GetNumberAsDouble();
        if (!(strength >= 0.0) || !std::isfinite(strength)) {
            gltf.fail(name + ": emissiveStrength is not a finite number >= 0");
        }
    }
    const glm::vec3 baseColor(glm::dvec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]));
    const auto metallic = static_cast<float>(pbr.metallicFactor);
    // Checked as the float it becomes: a finite double such as 1e300 is infinite as a float.
    const glm::vec3 emission(strength *
                             glm::dvec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]));
    if (!isFiniteFloat(emission)) {
        gltf.fail(name + ": emissiveStrength x emissiveFactor is beyond float range");
    }
    Material material = metallicRoughnessMaterial(m.name, baseColor, metallic,
                                                  static_cast<float>(pbr.roughnessFactor), emission);

    MaterialTextures& maps = material.textures;
    maps.colour = textureOf(gltf, textures, name + " baseColorTexture", pbr.baseColorTexture.index,
                            pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions, TextureEncoding::Colour);
    maps.roughnessMetallic =
        textureOf(gltf, textures, name + " metallicRoughnessTexture", pbr.metallicRoughnessTexture.index,
                  pbr.metallicRoughnessTexture.texCoord, pbr.metallicRoughnessTexture.extensions, TextureEncoding::Data);
    maps.emission = textureOf(gltf, textures, name + " emissiveTexture", m.emissiveTexture.index,
                              m.emissiveTexture.texCoord, m.emissiveTexture.extensions, TextureEncoding::Colour);
    maps.normal = textureOf(gltf, textures, name + " normalTexture", m.normalTexture.index, m.normalTexture.texCoord,
                            m.normalTexture.extensions, TextureEncoding::Data);
    maps.normalScale = static_cast<float>(m.normalTexture.scale);
    if (!std::isfinite(maps.normalScale)) gltf.fail(name + ": normalTexture scale is beyond float range");
    if (material.hasReflectanceTextures()) material.metallicRoughness = MetallicRoughness{baseColor, metallic};

    double cutoff = m.alphaCutoff;
    if (m.alphaMode == "BLEND") {
        gltf.warnOnce(name + ": alphaMode BLEND is rendered as MASK with alphaCutoff 0.5");
        cutoff = 0.5;
    }
    if (m.alphaMode == "MASK" || m.alphaMode == "BLEND") {
        if (!(cutoff >= 0.0) || !std::isfinite(cutoff)) gltf.fail(name + ": alphaCutoff is not a finite number >= 0");
        // alpha = baseColorFactor.a x texel alpha < cutoff <=> texel alpha < cutoff / factor.a;
        // without a texture the factor alone decides, through a one-texel coverage map.
        const double factorAlpha = pbr.baseColorFactor[3];
        maps.coverage = maps.colour ? maps.colour : std::make_shared<const Texture>(1, 1, 1, std::vector<float>{1.0f});
        maps.coverageChannel = 3;
        maps.alphaCutoff = factorAlpha > 0.0 ? static_cast<float>(cutoff / factorAlpha)
                                             : std::numeric_limits<float>::infinity();
        if (cutoff == 0.0) maps.coverage = nullptr;  // nothing is below 0
    }
    return material;
}

}  // namespace strata
