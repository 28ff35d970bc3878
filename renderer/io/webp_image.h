#pragma once
// WebP files through libwebp (glTF's EXT_texture_webp, and any texture file that is one): the
// header first, so that a texture's size is checked and budgeted before its pixels are allocated,
// then the pixels at 8 bits a channel, straight into the texture's storage.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "textures/texture.h"

namespace strata {

// A RIFF container of form type WEBP.
inline bool isWebp(std::string_view bytes) {
    return bytes.size() >= 12 && bytes.substr(0, 4) == "RIFF" && bytes.substr(8, 4) == "WEBP";
}

// The texture decodeWebp makes of `bytes`: 4 channels where the file has alpha, else 3. Throws
// strata::Error "NAME: cannot decode the texture (REASON)" for a header libwebp cannot read, and
// requirePlausibleImageSize's error (io/image_io.h) for a size the file cannot hold. An animated
// file is refused: a texture is one image.
TextureSize readWebpHeader(std::string_view bytes, const std::string& name);

// The 8-bit texels of that size, row-major, top row first.
std::vector<uint8_t> decodeWebp(std::string_view bytes, const std::string& name);

}  // namespace strata
