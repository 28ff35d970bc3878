#pragma once
// Texture files decoded into linear float textures (textures/texture.h): PNG, JPEG, TGA and BMP
// through stb_image at 8 bits per channel, EXR through OpenEXR (io/image_io.h's reader).
//
// 8-bit colour textures (base colour, diffuse, emission) hold sRGB-encoded values and are decoded
// with the exact sRGB curve through a 256-entry table; their alpha channel, and every channel of a
// data texture (coverage, normals, roughness/metallic), is linear, code / 255. stb_image's own
// float loader is not used: it applies a plain 2.2 gamma to every channel. EXR texels are linear
// already and taken as they are.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "textures/texture.h"

namespace strata {

enum class TextureEncoding {
    Colour,  // 8-bit RGB is sRGB-encoded
    Data,    // every channel linear
};

// The sRGB decoding of each 8-bit code (IEC 61966-2-1):
// c / 12.92 for c = code / 255 <= 0.04045, else ((c + 0.055) / 1.055)^2.4.
const std::array<float, 256>& srgbDecodingTable();

// The texture in a file's bytes; `name` stands for the file in messages. Throws strata::Error
// "NAME: cannot decode the texture (REASON)" for bytes no decoder reads.
Texture decodeTexture(std::string_view bytes, const std::string& name, TextureEncoding encoding);

}  // namespace strata
