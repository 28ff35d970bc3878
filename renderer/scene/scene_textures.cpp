#include "scene/scene_textures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "io/exr_header.h"
#include "util/error.h"
#include "util/printable.h"

namespace strata {
namespace {

// Which components of Texture::texel hold a texture's `channels` channels (texture.h).
constexpr std::array<std::array<int, 4>, 5> kChannelComponents{{{}, {0}, {0, 3}, {0, 1, 2}, {0, 1, 2, 3}}};

}  // namespace

FiniteTexture finiteNonNegative(const Texture& texture) {
    const auto& components = kChannelComponents[static_cast<size_t>(texture.channels())];
    const auto channels = static_cast<size_t>(texture.channels());
    float largest = 0.0f;
    std::vector<float> texels;
    texels.reserve(static_cast<size_t>(texture.width()) * texture.height() * channels);
    for (int y = 0; y < texture.height(); ++y) {
        for (int x = 0; x < texture.width(); ++x) {
            const glm::vec4 texel = texture.texel(x, y);
            for (size_t c = 0; c < channels; ++c) {
                const float value = texel[components[c]];
                if (std::isfinite(value) && value > largest) largest = value;
                texels.push_back(value);
            }
        }
    }
    size_t changed = 0;
    for (float& value : texels) {
        if (value >= 0.0f && value <= largest) continue;
        value = value > largest ? largest : 0.0f;  // +inf; NaN compares false and becomes 0
        ++changed;
    }
    const size_t values = texels.size();
    if (changed == 0) return {nullptr, 0, values};
    auto finite = std::make_shared<const Texture>(texture.width(), texture.height(), texture.channels(),
                                                  std::move(texels));
    return {std::move(finite), changed, values};
}

std::shared_ptr<const Texture> SceneTextures::file(const std::string& name, TextureEncoding encoding,
                                                   const std::string& where) {
    const SceneFile* found = bundle_.find(name);
    if (!found) {
        warnOnce(where + ": texture file " + quote(name) + " is missing; using the factor alone");
        return nullptr;
    }
    return bytes(name, found->bytes, encoding, where);
}

std::shared_ptr<const Texture> SceneTextures::bytes(const std::string& key, std::string_view data,
                                                    TextureEncoding encoding, const std::string& where) {
    const auto cached = decoded_.find({key, encoding});
    if (cached != decoded_.end()) return cached->second;
    // Named as the scene names it: `where` already says which file refers to it.
    const auto unusable = [&](const Error& error) {
        warnings_.push_back(where + ": " + error.what() + "; using the factor alone");
    };
    std::shared_ptr<const Texture> texture;
    std::optional<TextureSize> size;
    try {
        size = readTextureHeader(data, printable(key));
    } catch (const Error& error) {
        unusable(error);
    }
    if (size) {
        budget_.reserve(*size, where + ": texture " + quote(key));
        try {
            std::vector<std::string> damage;
            texture = std::make_shared<const Texture>(decodeTexture(data, printable(key), encoding, damage));
            if (!damage.empty() && damaged_.insert(key).second) {
                for (const std::string& line : damage) warnings_.push_back(where + ": " + line);
            }
        } catch (const Error& error) {
            unusable(error);
        }
    }
    if (texture && isExr(data)) {
        FiniteTexture finite = finiteNonNegative(*texture);
        if (finite.texture) {
            warnings_.push_back(where + ": " + quote(key) + ": " + std::to_string(finite.changed) + " of " +
                                std::to_string(finite.values) +
                                " texel values are NaN, infinite or negative; read as 0, or as the texture's "
                                "largest finite value for +inf");
            texture = std::move(finite.texture);
        }
    }
    decoded_.emplace(std::make_pair(key, encoding), texture);
    return texture;
}

void SceneTextures::warnOnce(const std::string& line) {
    if (std::find(warnings_.begin(), warnings_.end(), line) == warnings_.end()) warnings_.push_back(line);
}

}  // namespace strata
