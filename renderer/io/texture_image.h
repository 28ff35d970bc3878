#pragma once
// Texture files decoded into textures (textures/texture.h): JPEG through libjpeg
// (io/jpeg_image.h), WebP through libwebp (io/webp_image.h), PNG, TGA, BMP, GIF (its first
// frame), PSD and PNM through stb_image, all at 8 bits a channel and kept so; EXR through OpenEXR
// (io/image_io.h's reader) as floats.
//
// 8-bit colour textures (base colour, diffuse, emission) hold sRGB-encoded values, decoded at
// lookup with the exact sRGB curve (srgbDecodingTable); their alpha channel, and every channel of
// a data texture (coverage, normals, roughness/metallic), is linear, code / 255. stb_image's own
// float loader is not used: it applies a plain 2.2 gamma to every channel. EXR texels are linear
// already and taken as they are.
//
// A file's header is read first (readTextureHeader), so that a size the file cannot hold is
// refused, and a scene's texture budget applied (textures/texture_budget.h), before anything is
// allocated for its texels.
#include <string>
#include <string_view>
#include <vector>

#include "textures/texture.h"
#include "util/error.h"

namespace strata {

// The error "NAME: cannot decode the texture (REASON)" of a texture file that no decoder reads.
Error cannotDecodeTexture(const std::string& name, const std::string& reason);

// The size of the texture decodeTexture makes of `bytes`, from the file's header and structure
// alone. Throws strata::Error "NAME: ..." for bytes no decoder reads, a size beyond 2^28 texels,
// or one the file cannot hold: more texels than the densest coding of its format packs into its
// bytes (requirePlausibleImageSize, io/image_io.h), an EXR's missing chunks, a GIF whose first
// frame's data is too short for it.
TextureSize readTextureHeader(std::string_view bytes, const std::string& name);

// The texture in a file's bytes; `name` stands for the file in messages. Throws strata::Error
// "NAME: cannot decode the texture (REASON)" (or readTextureHeader's or readExr's error) for bytes
// no decoder reads. A file that decodes despite damage (a truncated JPEG or GIF, whose missing
// part decodes grey or blank) adds one line "NAME: ..." saying so to `warnings`.
Texture decodeTexture(std::string_view bytes, const std::string& name, TextureEncoding encoding,
                      std::vector<std::string>& warnings);

}  // namespace strata
