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
#include "materials/specular_glossiness.h"
#include "util/components.h"
#include "util/printable.h"

namespace strata {
namespace {

bool isFiniteFloat(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

Material metallicRoughnessMaterial(const std::string& name, const glm::vec3& baseColor, float metallic,
                                   float roughness, const glm::vec3& emission,
                                   const glm::vec3& dielectricF0 = glm::vec3(0.04f)) {
    Material material;
    material.name = name;
    const LayeredReflectance r = fromMetallicRoughness(baseColor, metallic, dielectricF0);
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
    // EXT_texture_webp names a WebP image in place of the core source, which is then a fallback
    // (or absent) for readers without WebP.
    int imageIndex = texture.source;
    if (const auto webp = texture.extensions.find("EXT_texture_webp"); webp != texture.extensions.end()) {
        const tinygltf::Value& source = webp->second.Get("source");
        if (!source.IsInt()) {
            gltf.fail(where + ": texture " + std::to_string(textureIndex) + ": EXT_texture_webp needs a source");
        }
        imageIndex = source.GetNumberAsInt();
    }
    if (imageIndex < 0) {
        gltf.warnOnce(where + ": texture " + std::to_string(textureIndex) + " has no image it can read; ignored");
        return nullptr;
    }
    const tinygltf::Image& image = gltf.element(gltf.model.images, imageIndex, where + ": image");
    const auto source = static_cast<size_t>(imageIndex);
    const std::string name = image.uri.empty() || image.uri.rfind("data:", 0) == 0
                                 ? "image " + std::to_string(source)
                                 : image.uri;
    if (source >= gltf.images.size() || gltf.images[source].empty()) {
        gltf.warnOnce(where + ": image " + quote(name) + " is missing; using the factor alone");
        return nullptr;
    }
    const auto decoded = textures.bytes(name, gltf.images[source], encoding, gltf.path + ": " + where);
    if (!decoded || texture.sampler < 0) return decoded;
    // The sampler's wrap modes and magnification filter ("Samplers"): NEAREST keeps pixel art's
    // texels square, as Blender's importer does (minification has no meaning without ray
    // footprints: every other lookup is bilinear).
    const tinygltf::Sampler& sampler = gltf.element(gltf.model.samplers, texture.sampler, where + ": sampler");
    const auto wrapOf = [&](int mode, const char* axis) {
        switch (mode) {
            case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
            case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
            case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
            default:
                gltf.warnOnce(where + ": sampler " + std::to_string(texture.sampler) + " has an unknown " + axis +
                              " " + std::to_string(mode) + "; the texture repeats");
                return TextureWrap::Repeat;
        }
    };
    const TextureSampling sampling{wrapOf(sampler.wrapS, "wrapS"), wrapOf(sampler.wrapT, "wrapT"),
                                   sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST};
    if (sampling == TextureSampling{}) return decoded;
    return std::make_shared<const Texture>(decoded->sampled(sampling));
}

// A material extension's object, or null when the material does not have it.
const tinygltf::Value* extensionOf(const tinygltf::Material& m, const std::string& name) {
    const auto it = m.extensions.find(name);
    return it == m.extensions.end() || !it->second.IsObject() ? nullptr : &it->second;
}

// The number `key` of an extension's object, `fallback` when it is absent; a failure naming the
// material, the extension and the key when it is not a number in [low, high].
float numberOf(const GltfModel& gltf, const tinygltf::Value& extension, const std::string& key, double fallback,
               double low, double high, const std::string& where) {
    if (!extension.Has(key)) return static_cast<float>(fallback);
    const tinygltf::Value& value = extension.Get(key);
    const double number = value.IsNumber() ? value.GetNumberAsDouble() : std::nan("");
    // Checked after narrowing, so that a double too large for a float cannot pass as finite.
    const auto narrowed = static_cast<float>(number);
    if (!std::isfinite(narrowed) || narrowed < low || narrowed > high) {
        gltf.fail(where + ": " + key + " is not a number in " + std::to_string(low) + ".." + std::to_string(high));
    }
    return narrowed;
}

// An extension's textureInfo `key` as the core's tinygltf::TextureInfo holds it (index -1: absent).
struct ExtensionTextureInfo {
    int index = -1;
    int texCoord = 0;
    tinygltf::ExtensionMap extensions;
};
ExtensionTextureInfo extensionTextureInfo(const GltfModel& gltf, const tinygltf::Value& extension,
                                          const std::string& key, const std::string& where) {
    ExtensionTextureInfo reference;
    if (!extension.Has(key)) return reference;
    const tinygltf::Value& info = extension.Get(key);
    const tinygltf::Value& index = info.Get("index");
    if (!info.IsObject() || !index.IsInt()) gltf.fail(where + " " + key + " needs a texture index");
    reference.index = index.GetNumberAsInt();
    if (info.Get("texCoord").IsInt()) reference.texCoord = info.Get("texCoord").GetNumberAsInt();
    if (info.Has("extensions") && info.Get("extensions").IsObject()) {
        const tinygltf::Value& nested = info.Get("extensions");
        for (const std::string& name : nested.Keys()) reference.extensions[name] = nested.Get(name);
    }
    return reference;
}

// The texture an extension's textureInfo `key` names, as textureOf reads a core one.
std::shared_ptr<const Texture> extensionTexture(GltfModel& gltf, SceneTextures& textures,
                                                const tinygltf::Value& extension, const std::string& key,
                                                const std::string& where, TextureEncoding encoding) {
    const ExtensionTextureInfo info = extensionTextureInfo(gltf, extension, key, where);
    return textureOf(gltf, textures, where + " " + key, info.index, info.texCoord, info.extensions, encoding);
}

// The factor `key` of an extension's object: N numbers in 0..1, `fallback` when absent.
template <size_t N>
std::array<float, N> unitFactors(const GltfModel& gltf, const tinygltf::Value& extension, const std::string& key,
                                 std::array<float, N> fallback, const std::string& where) {
    if (!extension.Has(key)) return fallback;
    const tinygltf::Value& value = extension.Get(key);
    const std::string malformed = where + ": " + key + " needs " + std::to_string(N) + " numbers in 0..1";
    if (!value.IsArray() || value.ArrayLen() != N) gltf.fail(malformed);
    std::array<float, N> factors{};
    for (size_t i = 0; i < N; ++i) {
        const tinygltf::Value& number = value.Get(static_cast<int>(i));
        factors[i] = number.IsNumber() ? static_cast<float>(number.GetNumberAsDouble()) : -1.0f;
        if (!(factors[i] >= 0.0f && factors[i] <= 1.0f)) gltf.fail(malformed);
    }
    return factors;
}

// KHR_materials_pbrSpecularGlossiness in place of the metallic-roughness parameters
// (specular_glossiness.h): Kd, Ks and Pr from its factors, the diffuse texture as the colour
// texture; returns the diffuse factor's alpha, which takes base colour alpha's part in MASK.
float applySpecularGlossiness(GltfModel& gltf, SceneTextures& textures, const tinygltf::Value& extension,
                              const std::string& name, Material& material) {
    const std::string where = name + ": KHR_materials_pbrSpecularGlossiness";
    const auto diffuse = unitFactors<4>(gltf, extension, "diffuseFactor", {1.0f, 1.0f, 1.0f, 1.0f}, where);
    const auto specular = unitFactors<3>(gltf, extension, "specularFactor", {1.0f, 1.0f, 1.0f}, where);
    const float glossiness = numberOf(gltf, extension, "glossinessFactor", 1.0, 0.0, 1.0, where);
    const SpecularGlossiness model{
        {diffuse[0], diffuse[1], diffuse[2]}, {specular[0], specular[1], specular[2]}, glossiness};
    const LayeredReflectance r = fromSpecularGlossiness(model.diffuse, model.specular);
    material.diffuse = r.diffuse;
    material.specular = r.specular;
    material.roughness = 1.0f - glossiness;
    MaterialTextures& maps = material.textures;
    maps.colour = extensionTexture(gltf, textures, extension, "diffuseTexture", name, TextureEncoding::Colour);
    // RGB sRGB, A (the glossiness) linear: the base colour's encoding.
    maps.specularGlossiness =
        extensionTexture(gltf, textures, extension, "specularGlossinessTexture", name, TextureEncoding::Colour);
    if (material.hasReflectanceTextures()) material.specularGlossiness = model;
    return diffuse[3];
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

// alphaMode MASK and BLEND: the coverage texture and cutoff or opacity of `maps` (material.h),
// whose colour texture holds the alpha, `colourAlpha` the factor's.
void applyAlphaMode(GltfModel& gltf, const tinygltf::Material& m, const std::string& name, double colourAlpha,
                    MaterialTextures& maps) {
    const double cutoff = m.alphaCutoff;
    if (m.alphaMode == "BLEND") {
        // Wholly opaque (a factor of 1 and no texel under it): no coverage to test.
        if (colourAlpha >= 1.0 && (!maps.colour || maps.colour->mean().a >= 1.0f)) return;
        maps.blendBy(static_cast<float>(std::max(colourAlpha, 0.0)), maps.colour, 3);
        return;
    }
    if (m.alphaMode == "MASK") {
        if (!(cutoff >= 0.0) || !std::isfinite(cutoff)) gltf.fail(name + ": alphaCutoff is not a finite number >= 0");
        // alpha = baseColorFactor.a x texel alpha < cutoff <=> texel alpha < cutoff / factor.a;
        // without a texture the factor alone decides, through a one-texel coverage map.
        maps.coverage = maps.colour ? maps.colour : std::make_shared<const Texture>(1, 1, 1, std::vector<float>{1.0f});
        maps.coverageChannel = 3;
        maps.alphaCutoff = colourAlpha > 0.0 ? static_cast<float>(cutoff / colourAlpha)
                                             : std::numeric_limits<float>::infinity();
        if (cutoff == 0.0) maps.coverage = nullptr;  // nothing is below 0
    }
}

}  // namespace

glm::dmat3 gltfTextureTransform(GltfModel& gltf, size_t index) {
    const tinygltf::Material& m = gltf.model.materials[index];
    const std::string name = "material '" + m.name + "' (" + std::to_string(index) + ")";
    const auto& pbr = m.pbrMetallicRoughness;
    // The textured slots the material reads: the specular-glossiness model's in place of the
    // metallic-roughness ones, whose textures are then a fallback that is not read.
    std::vector<std::pair<std::string, ExtensionTextureInfo>> slots;
    const auto core = [&](const char* slot, const auto& info) {  // a TextureInfo or NormalTextureInfo
        slots.emplace_back(slot, ExtensionTextureInfo{info.index, info.texCoord, info.extensions});
    };
    if (const tinygltf::Value* e = extensionOf(m, "KHR_materials_pbrSpecularGlossiness")) {
        for (const char* slot : {"diffuseTexture", "specularGlossinessTexture"}) {
            slots.emplace_back(slot, extensionTextureInfo(gltf, *e, slot, name));
        }
    } else {
        core("baseColorTexture", pbr.baseColorTexture);
        core("metallicRoughnessTexture", pbr.metallicRoughnessTexture);
    }
    core("emissiveTexture", m.emissiveTexture);
    core("normalTexture", m.normalTexture);
    std::string first;
    glm::dmat3 transform(1.0);
    for (const auto& [slot, info] : slots) {
        if (info.index < 0) continue;
        const glm::dmat3 own = transformOf(gltf, name + " " + slot, info.extensions);
        if (first.empty()) {
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
    // KHR_materials_unlit: the base colour shown as it is (material.h); of the rest only the alpha
    // that cuts out is read, and no other texture is decoded. (Its object is empty, which tinygltf
    // keeps as no value.)
    if (m.extensions.count("KHR_materials_unlit") > 0) {
        Material unlit;
        unlit.name = m.name;
        unlit.unlit = true;
        unlit.diffuse = baseColor;
        unlit.textures.colour = textureOf(gltf, textures, name + " baseColorTexture", pbr.baseColorTexture.index,
                                          pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions,
                                          TextureEncoding::Colour);
        applyAlphaMode(gltf, m, name, pbr.baseColorFactor[3], unlit.textures);
        return unlit;
    }
    const auto metallic = static_cast<float>(pbr.metallicFactor);
    // KHR_materials_ior and KHR_materials_specular: a dielectric's reflectance at normal
    // incidence, ((ior - 1) / (ior + 1))^2 times the specular colour, at most 1, times the factor.
    float ior = 1.5f;
    if (const tinygltf::Value* e = extensionOf(m, "KHR_materials_ior")) {
        ior = numberOf(gltf, *e, "ior", 1.5, 1.0, 10.0, name + ": KHR_materials_ior");
    }
    MetallicRoughness model{baseColor, metallic};
    // (In double: at ior 1.5 it rounds to the float 0.04 exactly, as the core model's constant.)
    model.specularColour = glm::vec3(static_cast<float>(std::pow((ior - 1.0) / (ior + 1.0), 2.0)));
    const tinygltf::Value* specular = extensionOf(m, "KHR_materials_specular");
    if (specular) {
        const std::string where = name + ": KHR_materials_specular";
        model.specularFactor = numberOf(gltf, *specular, "specularFactor", 1.0, 0.0, 1.0, where);
        if (specular->Has("specularColorFactor")) {
            const tinygltf::Value& c = specular->Get("specularColorFactor");
            if (!c.IsArray() || c.ArrayLen() != 3) gltf.fail(where + ": specularColorFactor needs 3 numbers");
            for (int i = 0; i < 3; ++i) {
                const float v = c.Get(i).IsNumber() ? static_cast<float>(c.Get(i).GetNumberAsDouble()) : -1.0f;
                if (!(v >= 0.0f) || !std::isfinite(v)) gltf.fail(where + ": specularColorFactor needs numbers >= 0");
                model.specularColour[i] *= v;
            }
        }
    }
    // Checked as the float it becomes: a finite double such as 1e300 is infinite as a float.
    const glm::vec3 emission(strength *
                             glm::dvec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]));
    if (!isFiniteFloat(emission)) {
        gltf.fail(name + ": emissiveStrength x emissiveFactor is beyond float range");
    }
    Material material = metallicRoughnessMaterial(m.name, baseColor, metallic,
                                                  static_cast<float>(pbr.roughnessFactor), emission,
                                                  model.dielectricF0());

    MaterialTextures& maps = material.textures;
    // The alpha that base colour alpha is in MASK: baseColorFactor's, or the diffuse factor's.
    double colourAlpha = pbr.baseColorFactor[3];
    const tinygltf::Value* specularGlossiness = extensionOf(m, "KHR_materials_pbrSpecularGlossiness");
    if (specularGlossiness) {
        colourAlpha = applySpecularGlossiness(gltf, textures, *specularGlossiness, name, material);
    } else {
        maps.colour = textureOf(gltf, textures, name + " baseColorTexture", pbr.baseColorTexture.index,
                                pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions, TextureEncoding::Colour);
        // Roughness in G, metallic in B (the channels' defaults in MaterialTextures).
        maps.roughness = textureOf(gltf, textures, name + " metallicRoughnessTexture",
                                   pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                                   pbr.metallicRoughnessTexture.extensions, TextureEncoding::Data);
        maps.metallic = maps.roughness;
        if (specular) {
            // The factor in the texture's alpha (linear), the colour in its RGB (sRGB).
            maps.specular = extensionTexture(gltf, textures, *specular, "specularTexture", name, TextureEncoding::Data);
            maps.specularColour =
                extensionTexture(gltf, textures, *specular, "specularColorTexture", name, TextureEncoding::Colour);
        }
    }
    maps.emission = textureOf(gltf, textures, name + " emissiveTexture", m.emissiveTexture.index,
                              m.emissiveTexture.texCoord, m.emissiveTexture.extensions, TextureEncoding::Colour);
    maps.normal = textureOf(gltf, textures, name + " normalTexture", m.normalTexture.index, m.normalTexture.texCoord,
                            m.normalTexture.extensions, TextureEncoding::Data);
    maps.normalScale = static_cast<float>(m.normalTexture.scale);
    if (!std::isfinite(maps.normalScale)) gltf.fail(name + ": normalTexture scale is beyond float range");

    // KHR_materials_transmission: the dielectric part (1 - metallic) transmits this share, through
    // a dielectric of the material's index and roughness tinted by the base colour;
    // KHR_materials_volume: a closed volume that absorbs, else (absent, or thickness 0) a thin wall.
    float transmission = 0.0f;
    if (const tinygltf::Value* e = extensionOf(m, "KHR_materials_transmission")) {
        const std::string where = name + ": KHR_materials_transmission";
        transmission = numberOf(gltf, *e, "transmissionFactor", 0.0, 0.0, 1.0, where);
        maps.transmission = extensionTexture(gltf, textures, *e, "transmissionTexture", name, TextureEncoding::Data);
    }
    material.transmission = transmission * (1.0f - metallic);
    material.ior = ior;
    material.transmissionFilter = baseColor;
    material.thinWalled = true;
    if (const tinygltf::Value* e = extensionOf(m, "KHR_materials_volume")) {
        const std::string where = name + ": KHR_materials_volume";
        material.thinWalled = numberOf(gltf, *e, "thicknessFactor", 0.0, 0.0, 1e30, where) == 0.0f;
        material.attenuationDistance =
            numberOf(gltf, *e, "attenuationDistance", std::numeric_limits<double>::infinity(), 0.0,
                     std::numeric_limits<double>::infinity(), where);
        if (!(material.attenuationDistance > 0.0f)) gltf.fail(where + ": attenuationDistance must be > 0");
        if (e->Has("attenuationColor")) {
            const tinygltf::Value& c = e->Get("attenuationColor");
            if (!c.IsArray() || c.ArrayLen() != 3) gltf.fail(where + ": attenuationColor needs 3 numbers");
            for (int i = 0; i < 3; ++i) {
                const float v = c.Get(i).IsNumber() ? static_cast<float>(c.Get(i).GetNumberAsDouble()) : -1.0f;
                if (!(v >= 0.0f && v <= 1.0f)) gltf.fail(where + ": attenuationColor needs numbers in 0..1");
                material.attenuationColor[i] = v;
            }
        }
    }
    if (material.thinWalled && material.transmission > 0.0f && material.roughness > 0.0f) {
        gltf.warnOnce(name + ": a thin-walled transmission renders smooth (its roughness applies to reflection)");
    }
    // KHR_materials_clearcoat: a coat of index 1.5 (F0 0.04) over the material.
    if (const tinygltf::Value* e = extensionOf(m, "KHR_materials_clearcoat")) {
        const std::string where = name + ": KHR_materials_clearcoat";
        material.clearcoat = numberOf(gltf, *e, "clearcoatFactor", 0.0, 0.0, 1.0, where);
        material.clearcoatRoughness = numberOf(gltf, *e, "clearcoatRoughnessFactor", 0.0, 0.0, 1.0, where);
        maps.clearcoat = extensionTexture(gltf, textures, *e, "clearcoatTexture", name, TextureEncoding::Data);
        maps.clearcoatRoughness =
            extensionTexture(gltf, textures, *e, "clearcoatRoughnessTexture", name, TextureEncoding::Data);
        maps.clearcoatNormal =
            extensionTexture(gltf, textures, *e, "clearcoatNormalTexture", name, TextureEncoding::Data);
        if (maps.clearcoatNormal && e->Get("clearcoatNormalTexture").Has("scale")) {
            const tinygltf::Value& scale = e->Get("clearcoatNormalTexture").Get("scale");
            maps.clearcoatNormalScale = scale.IsNumber() ? static_cast<float>(scale.GetNumberAsDouble()) : NAN;
            if (!std::isfinite(maps.clearcoatNormalScale)) {
                gltf.fail(where + ": clearcoatNormalTexture scale is not a number in float range");
            }
        }
    }
    // KHR_materials_sheen: a sheen over the layered model, under the coat (sheen.h).
    if (const tinygltf::Value* e = extensionOf(m, "KHR_materials_sheen")) {
        const std::string where = name + ": KHR_materials_sheen";
        const auto colour = unitFactors<3>(gltf, *e, "sheenColorFactor", {0.0f, 0.0f, 0.0f}, where);
        material.sheenColour = {colour[0], colour[1], colour[2]};
        material.sheenRoughness = numberOf(gltf, *e, "sheenRoughnessFactor", 0.0, 0.0, 1.0, where);
        maps.sheenColour = extensionTexture(gltf, textures, *e, "sheenColorTexture", name, TextureEncoding::Colour);
        maps.sheenRoughness =
            extensionTexture(gltf, textures, *e, "sheenRoughnessTexture", name, TextureEncoding::Data);
        if (material.sheenColour != glm::vec3(0.0f) && (material.transmission > 0.0f || material.roughness == 0.0f)) {
            gltf.warnOnce(where + ": not applied to a transmitting or perfectly smooth (roughness 0) material");
        }
    }
    if (material.hasReflectanceTextures() && !specularGlossiness) {
        model.transmission = transmission;
        material.metallicRoughness = model;
    }

    applyAlphaMode(gltf, m, name, colourAlpha, maps);
    return material;
}

}  // namespace strata
