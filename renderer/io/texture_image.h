#pragma once
// Texture files decoded into textures (textures/texture.h): PNG, JPEG, TGA and BMP through
// stb_image at 8 bits per channel and kept so, EXR through OpenEXR (io/image_io.h's reader) as
// floats.
//
// 8-bit colour textures (base colour, diffuse, emission) hold sRGB-encoded values, decoded at
// lookup with the exact sRGB curve (srgbDecodingTable); their alpha channel, and every channel of
// a data texture (coverage, normals, roughness/metallic), is linear, code / 255. stb_image's own
// float loader is not used: it applies a plain 2.2 gamma to every channel. EXR texels are linear
// already and taken as they are.
#include <string>
#include <string_view>

#include "textures/texture.h"

namespace strata {

// The texture in a file's bytes; `name` stands for the file in messages. Throws strata::Error
// "NAME: cannot decode the texture (REASON)" for bytes no decoder reads.
Texture decodeTexture(std::string_view bytes, const std::string& name, TextureEncoding encoding);

}  // namespace strata
