#include "io/webp_image.h"

#include <string>
#include <webp/decode.h>

#include "io/image_io.h"
#include "io/texture_image.h"
#include "util/error.h"

namespace strata {
namespace {

// The densest WebP coding taken as plausible. libwebp's lossless encoder packs a flat 16383 x
// 16383 image into 26,000 pixels a byte, and its lossy one 560; the format itself can code a
// flat image in fewer bits still (a single-symbol Huffman code takes none), so the bound leaves
// headroom over the encoder and the texture budget (textures/texture_budget.h) caps the rest.
constexpr long long kWebpPixelsPerByte = 1 << 16;

std::string webpStatusText(VP8StatusCode status) {
    switch (status) {
        case VP8_STATUS_BITSTREAM_ERROR: return "a damaged WebP header";
        case VP8_STATUS_UNSUPPORTED_FEATURE: return "a WebP feature libwebp does not read";
        case VP8_STATUS_NOT_ENOUGH_DATA: return "a WebP file that ends inside its header";
        default: return "libwebp status " + std::to_string(static_cast<int>(status));
    }
}

WebPBitstreamFeatures webpFeatures(std::string_view bytes, const std::string& name) {
    WebPBitstreamFeatures features;
    const VP8StatusCode status =
        WebPGetFeatures(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), &features);
    if (status != VP8_STATUS_OK) throw cannotDecodeTexture(name, webpStatusText(status));
    if (features.has_animation) throw cannotDecodeTexture(name, "an animated WebP; a texture is one image");
    return features;
}

}  // namespace

TextureSize readWebpHeader(std::string_view bytes, const std::string& name) {
    const WebPBitstreamFeatures features = webpFeatures(bytes, name);
    requirePlausibleImageSize(features.width, features.height, bytes.size(), name, kWebpPixelsPerByte);
    return {features.width, features.height, features.has_alpha ? 4 : 3};
}

std::vector<uint8_t> decodeWebp(std::string_view bytes, const std::string& name) {
    const TextureSize size = readWebpHeader(bytes, name);
    std::vector<uint8_t> texels(size.bytes());
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
    const int stride = size.width * size.channels;
    const uint8_t* decoded = size.channels == 4
                                 ? WebPDecodeRGBAInto(data, bytes.size(), texels.data(), texels.size(), stride)
                                 : WebPDecodeRGBInto(data, bytes.size(), texels.data(), texels.size(), stride);
    if (!decoded) throw cannotDecodeTexture(name, "damaged or truncated WebP data");
    return texels;
}

}  // namespace strata
