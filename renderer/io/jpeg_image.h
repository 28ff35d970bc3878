#pragma once
// JPEG files through libjpeg(-turbo): the header first, so that a texture's size is checked and
// budgeted before its pixels are allocated, then the pixels at 8 bits a channel, straight into
// the texture's storage, a row at a time.
//
// libjpeg, unlike stb_image, says when the data of a JPEG ends before its image does (a truncated
// download, a file cut short and closed with an end-of-image marker): it decodes what is there,
// the rest grey, and warns; so does Strata, naming the file.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "textures/texture.h"

namespace strata {

inline bool isJpeg(std::string_view bytes) { return bytes.substr(0, 3) == "\xff\xd8\xff"; }

// The texture decodeJpeg makes of `bytes`: 1 channel for grey, 3 for colour (YCbCr, RGB, CMYK).
// Throws strata::Error "NAME: cannot decode the texture (REASON)" for a header libjpeg cannot
// read, and requirePlausibleImageSize's error (io/image_io.h) for a size the file cannot hold.
TextureSize readJpegHeader(std::string_view bytes, const std::string& name);

// The 8-bit texels of that size, row-major, top row first. Damage that libjpeg decodes through
// adds the line "NAME: damaged or truncated JPEG (libjpeg: MESSAGE)" to `warnings`.
std::vector<uint8_t> decodeJpeg(std::string_view bytes, const std::string& name,
                                std::vector<std::string>& warnings);

}  // namespace strata
