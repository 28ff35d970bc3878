#pragma once
// The textures of a scene's materials, decoded from the bundle's files (or, for glTF, from bytes
// inside the model), each file once per encoding, against the scene's texture budget
// (textures/texture_budget.h). A texture that is missing from the bundle or that no decoder reads
// is a warning naming the file, and the material renders with its constant alone: every
// comparable tool opens such a scene. One that would take the scene's textures over the budget is
// an error, raised before its texels are allocated.
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "io/texture_image.h"
#include "scene/scene_format.h"
#include "textures/texture_budget.h"

namespace strata {

// A texture's texels made finite and non-negative, as every texture Strata renders holds them
// (colours, emission, coverage, roughness and metallic, normal maps encoded in 0..1): NaN and
// negative values read as 0, +inf as the texture's largest finite value. An EXR file can hold any float,
// and one NaN or negative texel of an emitter would turn the image black or negative.
struct FiniteTexture {
    std::shared_ptr<const Texture> texture;  // null when every value was already so
    size_t changed = 0;                      // the values changed
    size_t values = 0;                       // of all the texture's values
};
FiniteTexture finiteNonNegative(const Texture& texture);

class SceneTextures {
public:
    // `warnings` receives one line per texture that cannot be used, or that decodes despite
    // damage (once per file); both outlive this. `budget` counts every texture decoded.
    SceneTextures(const SceneBundle& bundle, std::vector<std::string>& warnings, TextureBudget budget)
        : bundle_(bundle), warnings_(warnings), budget_(budget) {}

    // The bundle file `name` (relative to the main file's folder) as a texture; null when it is
    // missing or unreadable, with a warning that starts with `where` ("spider.mtl:10: map_Kd").
    // Throws strata::Error "WHERE: texture 'NAME' is ..." (TextureBudget::reserve) when it would
    // go over the budget.
    std::shared_ptr<const Texture> file(const std::string& name, TextureEncoding encoding,
                                        const std::string& where);
    // The same for bytes the scene file holds itself; `key` names them (uniquely) in the cache.
    // An EXR texture's texels are made finite and non-negative (finiteNonNegative), with a
    // warning naming it and how many were not.
    std::shared_ptr<const Texture> bytes(const std::string& key, std::string_view data,
                                         TextureEncoding encoding, const std::string& where);

    // What the textures decoded so far take.
    const TextureBudget& budget() const { return budget_; }

private:
    void warnOnce(const std::string& line);

    const SceneBundle& bundle_;
    std::vector<std::string>& warnings_;
    TextureBudget budget_;
    std::map<std::pair<std::string, TextureEncoding>, std::shared_ptr<const Texture>> decoded_;
    std::set<std::string> damaged_;  // the files whose damage was reported
};

}  // namespace strata
