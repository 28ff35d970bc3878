#pragma once
// An MTL texture statement ("map_Kd -bm 1 -s 2 2 textures\wood grain.jpg"): its options and its
// file. The options are those of the MTL specification, each with its number of arguments;
// -o, -s and -t take one to three numbers. The file is the rest of the line after the options, so
// a name may hold spaces; '\' separators (Windows tools write them) read as '/'.
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <glm/vec2.hpp>

namespace strata {

struct MtlTextureStatement {
    std::string file;           // as written, '\' turned to '/'
    float bumpMultiplier = 1.0f;  // -bm
    glm::vec2 offset{0.0f};     // -o u v
    glm::vec2 scale{1.0f};      // -s u v
    std::optional<char> channel;  // -imfchan r, g, b, m, l or z
    bool clamp = false;           // -clamp on: the edge texels stretch out (TextureWrap::ClampToEdge)
    std::string unknownOption;  // the first option that is not the specification's, if any
};

// The texture keys Strata reads: map_Kd, map_Ke, map_d, norm, map_Bump, bump, map_Pr, map_Pm.
bool isMtlTextureKey(std::string_view key);

// The statement of `words` (the key first); empty when it names no file.
std::optional<MtlTextureStatement> parseMtlTextureStatement(const std::vector<std::string_view>& words);

// The bundle name of a texture `file` that an MTL named `mtlName` (relative to the main file's
// folder) refers to: relative to the MTL's own folder, normalised ("sub/./a.png" -> "sub/a.png").
std::string textureFileName(const std::string& mtlName, const std::string& file);

}  // namespace strata
