#pragma once
// The textures of a scene's materials, decoded from the bundle's files (or, for glTF, from bytes
// inside the model), each file once per encoding. A texture that is missing from the bundle or
// that no decoder reads is a warning naming the file, and the material renders with its constant
// alone: every comparable tool opens such a scene.
#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "io/texture_image.h"
#include "scene/scene_format.h"

namespace strata {

class SceneTextures {
public:
    // `warnings` receives one line per texture that cannot be used, or that decodes despite
    // damage (once per file); both outlive this.
    SceneTextures(const SceneBundle& bundle, std::vector<std::string>& warnings)
        : bundle_(bundle), warnings_(warnings) {}

    // The bundle file `name` (relative to the main file's folder) as a texture; null when it is
    // missing or unreadable, with a warning that starts with `where` ("spider.mtl:10: map_Kd").
    std::shared_ptr<const Texture> file(const std::string& name, TextureEncoding encoding, const std::string& where);
    // The same for bytes the scene file holds itself; `key` names them (uniquely) in the cache.
    std::shared_ptr<const Texture> bytes(const std::string& key, std::string_view data, TextureEncoding encoding,
                                         const std::string& where);

private:
    const SceneBundle& bundle_;
    std::vector<std::string>& warnings_;
    std::map<std::pair<std::string, TextureEncoding>, std::shared_ptr<const Texture>> decoded_;
    std::set<std::string> damaged_;  // the files whose damage was reported
};

}  // namespace strata
