#include "scene/scene_textures.h"

#include <algorithm>
#include <optional>

#include "util/error.h"

namespace strata {

std::shared_ptr<const Texture> SceneTextures::file(const std::string& name, TextureEncoding encoding,
                                                   const std::string& where) {
    const SceneFile* found = bundle_.find(name);
    if (!found) {
        warnOnce(where + ": texture file '" + name + "' is missing; using the factor alone");
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
        size = readTextureHeader(data, key);
    } catch (const Error& error) {
        unusable(error);
    }
    if (size) {
        budget_.reserve(*size, where + ": texture '" + key + "'");
        try {
            std::vector<std::string> damage;
            texture = std::make_shared<const Texture>(decodeTexture(data, key, encoding, damage));
            if (!damage.empty() && damaged_.insert(key).second) {
                for (const std::string& line : damage) warnings_.push_back(where + ": " + line);
            }
        } catch (const Error& error) {
            unusable(error);
        }
    }
    decoded_.emplace(std::make_pair(key, encoding), texture);
    return texture;
}

void SceneTextures::warnOnce(const std::string& line) {
    if (std::find(warnings_.begin(), warnings_.end(), line) == warnings_.end()) warnings_.push_back(line);
}

}  // namespace strata
