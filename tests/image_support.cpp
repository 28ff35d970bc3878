#include "image_support.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <jpeglib.h>

namespace strata::test {
namespace {

void appendBigEndian(std::string& out, uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((value >> shift) & 0xff);
}

void appendLittleEndian(std::string& out, uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) out += static_cast<char>((value >> (8 * i)) & 0xff);
}

uint32_t crc32(const std::string& bytes) {
    uint32_t crc = 0xffffffffu;
    for (const char byte : bytes) {
        crc ^= static_cast<unsigned char>(byte);
        for (int bit = 0; bit < 8; ++bit) crc = crc & 1 ? (crc >> 1) ^ 0xedb88320u : crc >> 1;
    }
    return ~crc;
}

// A zlib stream of stored (uncompressed) deflate blocks.
std::string storedZlib(const std::string& data) {
    std::string out = "\x78\x01";
    size_t at = 0;
    do {
        const size_t length = std::min<size_t>(data.size() - at, 65535);
        const bool last = at + length == data.size();
        out += static_cast<char>(last ? 1 : 0);
        appendLittleEndian(out, length, 2);
        appendLittleEndian(out, ~length & 0xffff, 2);
        out += data.substr(at, length);
        at += length;
    } while (at < data.size());
    uint32_t a = 1, b = 0;
    for (const char byte : data) {
        a = (a + static_cast<unsigned char>(byte)) % 65521;
        b = (b + a) % 65521;
    }
    appendBigEndian(out, b << 16 | a);
    return out;
}

std::string pngHeader(int width, int height, int bitDepth, int colourType) {
    std::string ihdr;
    appendBigEndian(ihdr, static_cast<uint32_t>(width));
    appendBigEndian(ihdr, static_cast<uint32_t>(height));
    ihdr += {static_cast<char>(bitDepth), static_cast<char>(colourType), 0, 0, 0};
    return std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr);
}

std::string gifHeader(int width, int height) {
    std::string gif = "GIF89a";
    appendLittleEndian(gif, static_cast<uint64_t>(width), 2);
    appendLittleEndian(gif, static_cast<uint64_t>(height), 2);
    gif += std::string("\x81\0\0", 3);  // a global table of 4 colours
    gif += std::string("\0\0\0\xff\xff\xff\xff\0\0\0\xff\0", 12);
    gif += '\x2c';
    appendLittleEndian(gif, 0, 4);
    appendLittleEndian(gif, static_cast<uint64_t>(width), 2);
    appendLittleEndian(gif, static_cast<uint64_t>(height), 2);
    gif += '\0';
    gif += '\x02';  // LZW minimum code size
    return gif;
}

// `data` as GIF sub-blocks of up to 255 bytes, ended by an empty one.
std::string subBlocks(const std::string& data) {
    std::string out;
    for (size_t at = 0; at < data.size(); at += 255) {
        const std::string block = data.substr(at, 255);
        out += static_cast<char>(block.size());
        out += block;
    }
    return out + '\0';
}

}  // namespace

std::string pngChunk(const std::string& type, const std::string& data) {
    std::string chunk;
    appendBigEndian(chunk, static_cast<uint32_t>(data.size()));
    chunk += type + data;
    appendBigEndian(chunk, crc32(type + data));
    return chunk;
}

std::string pngFile(int width, int height, int bitDepth, int colourType, const std::string& rows,
                    const std::string& chunksBeforeData) {
    return pngHeader(width, height, bitDepth, colourType) + chunksBeforeData +
           pngChunk("IDAT", storedZlib(rows)) + pngChunk("IEND", "");
}

std::string forgedPng(int width, int height, int bitDepth, int colourType, size_t dataBytes) {
    return pngHeader(width, height, bitDepth, colourType) + pngChunk("IDAT", std::string(dataBytes, '\x5a')) +
           pngChunk("IEND", "");
}

std::string gifFile(int width, int height, const std::vector<unsigned char>& indices) {
    // Each index a literal 3-bit code after a clear code (4), so that the decoder's dictionary,
    // and with it the code width, never grows; then the end code (5).
    std::string data;
    uint32_t bits = 0;
    int count = 0;
    const auto put = [&](uint32_t code) {
        bits |= code << count;
        for (count += 3; count >= 8; count -= 8, bits >>= 8) data += static_cast<char>(bits & 0xff);
    };
    for (const unsigned char index : indices) {
        put(4);
        put(index);
    }
    put(5);
    if (count > 0) data += static_cast<char>(bits & 0xff);
    return gifHeader(width, height) + subBlocks(data) + ';';
}

std::string forgedGif(int width, int height, size_t dataBytes) {
    std::mt19937 random(7);
    std::string data(dataBytes, '\0');
    for (char& byte : data) byte = static_cast<char>(random() & 0xff);
    return gifHeader(width, height) + subBlocks(data) + ';';
}

std::string jpegFile(int width, int height, int channels, const std::vector<unsigned char>& pixels,
                     bool progressive) {
    jpeg_compress_struct jpeg{};
    jpeg_error_mgr errors{};
    jpeg.err = jpeg_std_error(&errors);
    jpeg_create_compress(&jpeg);
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&jpeg, &buffer, &size);
    jpeg.image_width = static_cast<JDIMENSION>(width);
    jpeg.image_height = static_cast<JDIMENSION>(height);
    jpeg.input_components = channels;
    jpeg.in_color_space = channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&jpeg);
    jpeg_set_quality(&jpeg, 90, TRUE);
    if (progressive) jpeg_simple_progression(&jpeg);
    jpeg_start_compress(&jpeg, TRUE);
    while (jpeg.next_scanline < jpeg.image_height) {
        auto* row = const_cast<unsigned char*>(pixels.data()) +
                    static_cast<size_t>(jpeg.next_scanline) * static_cast<size_t>(width * channels);
        jpeg_write_scanlines(&jpeg, &row, 1);
    }
    jpeg_finish_compress(&jpeg);
    jpeg_destroy_compress(&jpeg);
    std::string out(reinterpret_cast<const char*>(buffer), size);
    std::free(buffer);
    return out;
}

std::string truncatedJpeg() {
    std::vector<unsigned char> pixels(32 * 32 * 3);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<unsigned char>(i * 7);
    const std::string jpeg = jpegFile(32, 32, 3, pixels);
    const size_t scan = jpeg.find("\xff\xda");
    return jpeg.substr(0, (scan + jpeg.size()) / 2) + "\xff\xd9";
}

std::string forgedJpeg(int width, int height, size_t totalBytes) {
    std::mt19937 random(11);
    std::vector<unsigned char> noise(512 * 512 * 3);
    for (unsigned char& value : noise) value = static_cast<unsigned char>(random() & 0xff);
    std::string jpeg = jpegFile(512, 512, 3, noise, false);
    const size_t frame = jpeg.find("\xff\xc0");
    // The frame header: marker, length (2), precision (1), height (2), width (2).
    jpeg[frame + 5] = static_cast<char>(height >> 8), jpeg[frame + 6] = static_cast<char>(height & 0xff);
    jpeg[frame + 7] = static_cast<char>(width >> 8), jpeg[frame + 8] = static_cast<char>(width & 0xff);
    jpeg.resize(totalBytes - 2);
    return jpeg + "\xff\xd9";
}

std::string forgedExr(int width, int height) {
    const auto attribute = [](const std::string& name, const std::string& type, const std::string& value) {
        std::string out = name + '\0' + type + '\0';
        appendLittleEndian(out, value.size(), 4);
        return out + value;
    };
    const auto integers = [](std::initializer_list<int> values) {
        std::string out;
        for (const int v : values) appendLittleEndian(out, static_cast<uint32_t>(v), 4);
        return out;
    };
    std::string channels;
    for (const char* channel : {"B", "G", "R"}) {
        // name, pixel type 2 (float), pLinear and reserved, x and y sampling 1
        channels += std::string(channel) + '\0' + integers({2, 0, 1, 1});
    }
    channels += '\0';
    const std::string window = integers({0, 0, width - 1, height - 1});
    std::string exr = std::string("\x76\x2f\x31\x01\x02\0\0\0", 8);
    exr += attribute("channels", "chlist", channels);
    exr += attribute("compression", "compression", std::string(1, '\0'));
    exr += attribute("dataWindow", "box2i", window);
    exr += attribute("displayWindow", "box2i", window);
    exr += attribute("lineOrder", "lineOrder", std::string(1, '\0'));
    exr += attribute("pixelAspectRatio", "float", integers({0x3f800000}));
    exr += attribute("screenWindowCenter", "v2f", integers({0, 0}));
    exr += attribute("screenWindowWidth", "float", integers({0x3f800000}));
    exr += '\0';
    // Each line's chunk: its y (4 bytes), its size (4) and 12 bytes a pixel.
    const uint64_t first = exr.size() + 8 * static_cast<uint64_t>(height);
    const uint64_t line = 8 + 12 * static_cast<uint64_t>(width);
    for (int y = 0; y < height; ++y) appendLittleEndian(exr, first + static_cast<uint64_t>(y) * line, 8);
    return exr;
}

}  // namespace strata::test
