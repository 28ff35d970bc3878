#include "io/texture_image.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <stb_image.h>

#include "io/exr_header.h"
#include "io/image_io.h"
#include "io/jpeg_image.h"
#include "io/webp_image.h"
#include "util/error.h"

namespace strata {
namespace {

// GIF's LZW codes are at most 12 bits and stand for at most 4096 pixels each (its dictionary's
// longest string): no more than 4096 pixels per 1.5 bytes of a frame's data.
constexpr long long kGifPixelsPerByte = 4096 * 8 / 12 + 1;

bool isPng(std::string_view bytes) { return bytes.size() >= 8 && bytes.substr(0, 8) == "\x89PNG\r\n\x1a\n"; }
bool isGif(std::string_view bytes) { return bytes.size() >= 6 && bytes.substr(0, 4) == "GIF8"; }

uint32_t bigEndian32(std::string_view bytes, size_t at) {
    const auto byte = [&](size_t i) {
        return static_cast<uint32_t>(static_cast<unsigned char>(bytes[at + i]));
    };
    return byte(0) << 24 | byte(1) << 16 | byte(2) << 8 | byte(3);
}

int littleEndian16(std::string_view bytes, size_t at) {
    return static_cast<unsigned char>(bytes[at]) | static_cast<unsigned char>(bytes[at + 1]) << 8;
}

// Whether a grey or RGB PNG has a tRNS chunk (before its image data), which stb_image decodes as
// an alpha channel that its header query does not count.
bool pngHasTransparentColour(std::string_view png) {
    constexpr size_t kColourTypeAt = 8 + 8 + 9;
    if (png.size() <= kColourTypeAt || (png[kColourTypeAt] != 0 && png[kColourTypeAt] != 2)) return false;
    for (size_t at = 8; at + 8 <= png.size();) {
        const std::string_view type = png.substr(at + 4, 4);
        if (type == "tRNS") return true;
        if (type == "IDAT") return false;
        at += 12 + static_cast<size_t>(bigEndian32(png, at));
    }
    return false;
}

// The first image of a GIF, the only one stb_image decodes: its size and how many bytes of LZW
// data the file holds for it; `truncated` when the file ends inside that data.
struct GifFrame {
    int width = 0;
    int height = 0;
    size_t dataBytes = 0;
    bool truncated = false;
};

// Skips a GIF's data sub-blocks from `at` (each a length byte and that many bytes, ended by a
// length of 0), counting their bytes; returns the position after them, or npos at the file's end.
size_t skipSubBlocks(std::string_view gif, size_t at, size_t* dataBytes) {
    while (at < gif.size()) {
        const size_t length = static_cast<unsigned char>(gif[at++]);
        if (length == 0) return at;
        if (dataBytes) *dataBytes += std::min(length, gif.size() - at);
        at += length;
    }
    return std::string_view::npos;
}

// Null when the file has no image before it ends (stb_image then says what is wrong).
std::optional<GifFrame> firstGifFrame(std::string_view gif) {
    constexpr size_t kScreenDescriptorEnd = 13;
    if (gif.size() < kScreenDescriptorEnd) return std::nullopt;
    const auto colourTableBytes = [](unsigned char flags) {
        return flags & 0x80 ? 3 * (size_t{2} << (flags & 7)) : 0;
    };
    size_t at = kScreenDescriptorEnd + colourTableBytes(static_cast<unsigned char>(gif[10]));
    while (at < gif.size()) {
        const auto block = static_cast<unsigned char>(gif[at++]);
        if (block == 0x21 && at < gif.size()) {  // an extension: its label, then sub-blocks
            at = skipSubBlocks(gif, at + 1, nullptr);
        } else if (block == 0x2c && at + 9 < gif.size()) {  // an image descriptor
            GifFrame frame{littleEndian16(gif, at + 4), littleEndian16(gif, at + 6), 0, false};
            at += 9 + colourTableBytes(static_cast<unsigned char>(gif[at + 8])) + 1;  // + LZW code size
            frame.truncated = skipSubBlocks(gif, at, &frame.dataBytes) == std::string_view::npos;
            return frame;
        } else {
            return std::nullopt;
        }
    }
    return std::nullopt;
}

Texture decodeExr(std::string_view bytes, const std::string& name) {
    const Image image = readExr(bytes, name);
    std::vector<float> texels;
    texels.reserve(image.pixels.size() * 3);
    for (const glm::vec3& p : image.pixels) texels.insert(texels.end(), {p.x, p.y, p.z});
    return Texture(image.width, image.height, 3, std::move(texels));
}

}  // namespace

Error cannotDecodeTexture(const std::string& name, const std::string& reason) {
    return Error(name + ": cannot decode the texture (" + reason + ")");
}

TextureSize readTextureHeader(std::string_view bytes, const std::string& name) {
    // readExrHeader's and readJpegHeader's messages name the file already.
    if (isExr(bytes)) return readExrHeader(bytes, name);
    if (isJpeg(bytes)) return readJpegHeader(bytes, name);
    if (isWebp(bytes)) return readWebpHeader(bytes, name);
    if (bytes.empty()) throw cannotDecodeTexture(name, "the file is empty");
    if (bytes.size() > static_cast<size_t>(INT32_MAX)) throw cannotDecodeTexture(name, "larger than 2 GB");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = static_cast<int>(bytes.size());
    if (stbi_is_hdr_from_memory(data, size)) {
        throw cannotDecodeTexture(name, "Radiance HDR textures are not read; use EXR");
    }
    TextureSize texels;
    if (!stbi_info_from_memory(data, size, &texels.width, &texels.height, &texels.channels)) {
        throw cannotDecodeTexture(name, stbi_failure_reason());
    }
    requirePlausibleImageSize(texels.width, texels.height, bytes.size(), name);
    if (isPng(bytes) && pngHasTransparentColour(bytes)) ++texels.channels;
    if (isGif(bytes)) {
        const std::optional<GifFrame> frame = firstGifFrame(bytes);
        if (frame && frame->width > 0 && frame->height > 0) {
            requirePlausibleImageSize(frame->width, frame->height, frame->dataBytes, name, kGifPixelsPerByte);
        }
    }
    return texels;
}

Texture decodeTexture(std::string_view bytes, const std::string& name, TextureEncoding encoding,
                      std::vector<std::string>& warnings) {
    if (isExr(bytes)) return decodeExr(bytes, name);
    const TextureSize texels = readTextureHeader(bytes, name);
    if (isJpeg(bytes)) {
        return Texture(texels.width, texels.height, texels.channels, decodeJpeg(bytes, name, warnings),
                       encoding);
    }
    if (isWebp(bytes)) {
        return Texture(texels.width, texels.height, texels.channels, decodeWebp(bytes, name), encoding);
    }
    if (isGif(bytes)) {
        const std::optional<GifFrame> frame = firstGifFrame(bytes);
        if (frame && frame->truncated) {
            warnings.push_back(name +
                               ": truncated GIF (the file ends inside its image); the rest decodes blank");
        }
    }
    // The channels asked for explicitly: stb_image's count for a PNG with a transparent colour is
    // one short of what it decodes.
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()),
                              &width, &height, &channels, texels.channels),
        stbi_image_free);
    if (!pixels) throw cannotDecodeTexture(name, stbi_failure_reason());
    if (width != texels.width || height != texels.height) throw cannotDecodeTexture(name, "its size reads two ways");
    return Texture(width, height, texels.channels,
                   std::vector<uint8_t>(pixels.get(), pixels.get() + texels.bytes()), encoding);
}

}  // namespace strata
