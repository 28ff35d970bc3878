#include "io/jpeg_image.h"

#include <cstdio>
#include <stdexcept>
// jpeglib.h needs size_t and FILE declared before it.
#include <jpeglib.h>

#include "io/image_io.h"
#include "util/error.h"

namespace strata {
namespace {

// A Huffman-coded JPEG spends at least one bit on each 8 x 8 block of its full-resolution
// component (the DC code of its first scan; a sequential one two, with the end-of-block code):
// at most 512 pixels a byte. Arithmetic coding has no such floor; its rare files are held to the
// generic bound, which only a nearly flat image of them could exceed.
constexpr long long kHuffmanPixelsPerByte = 64 * 8;

// libjpeg's error manager, extended by the first warning it gave. Standard layout with the
// manager first, so that libjpeg's pointer to it is a pointer to this.
struct JpegErrors {
    jpeg_error_mgr manager;
    char firstWarning[JMSG_LENGTH_MAX];
};

// libjpeg's fatal errors unwind back to JpegDecoder, which destroys the decompressor.
[[noreturn]] void throwError(j_common_ptr jpeg) {
    char message[JMSG_LENGTH_MAX];
    jpeg->err->format_message(jpeg, message);
    throw std::runtime_error(message);
}

// Warnings (level -1) are counted and the first kept; trace messages (level >= 0) dropped.
void keepFirstWarning(j_common_ptr jpeg, int level) {
    if (level >= 0) return;
    auto* errors = reinterpret_cast<JpegErrors*>(jpeg->err);
    if (errors->manager.num_warnings++ == 0) errors->manager.format_message(jpeg, errors->firstWarning);
}

// libjpeg's decompressor with its error manager, destroyed on every way out.
struct Decompressor {
    Decompressor() {
        jpeg.err = jpeg_std_error(&errors.manager);
        errors.manager.error_exit = throwError;
        errors.manager.emit_message = keepFirstWarning;
        jpeg_create_decompress(&jpeg);
    }
    Decompressor(const Decompressor&) = delete;
    Decompressor& operator=(const Decompressor&) = delete;
    ~Decompressor() { jpeg_destroy_decompress(&jpeg); }

    JpegErrors errors{};
    jpeg_decompress_struct jpeg{};
};

class JpegDecoder {
public:
    // Reads the header; throws strata::Error naming the file.
    JpegDecoder(std::string_view bytes, const std::string& name) : name_(name) {
        jpeg_decompress_struct& jpeg = decompressor_.jpeg;
        attempt([&] {
            jpeg_mem_src(&jpeg, reinterpret_cast<const unsigned char*>(bytes.data()),
                         static_cast<unsigned long>(bytes.size()));
            jpeg_read_header(&jpeg, TRUE);
        });
        switch (jpeg.jpeg_color_space) {
            case JCS_GRAYSCALE: jpeg.out_color_space = JCS_GRAYSCALE; break;
            case JCS_CMYK:
            case JCS_YCCK: jpeg.out_color_space = JCS_CMYK; break;
            case JCS_UNKNOWN:
                throw Error(name + ": cannot decode the texture (a JPEG of unknown colour space)");
            default: jpeg.out_color_space = JCS_RGB; break;
        }
        requirePlausibleImageSize(jpeg.image_width, jpeg.image_height, bytes.size(), name,
                                  jpeg.arith_code ? kDensestPixelsPerByte : kHuffmanPixelsPerByte);
    }

    TextureSize size() const {
        const jpeg_decompress_struct& jpeg = decompressor_.jpeg;
        const int channels = jpeg.out_color_space == JCS_GRAYSCALE ? 1 : 3;
        return {static_cast<int>(jpeg.image_width), static_cast<int>(jpeg.image_height), channels, 1};
    }

    std::vector<uint8_t> decode(std::vector<std::string>& warnings) {
        jpeg_decompress_struct& jpeg = decompressor_.jpeg;
        const TextureSize texels = size();
        const size_t rowBytes = static_cast<size_t>(texels.width) * static_cast<size_t>(texels.channels);
        std::vector<uint8_t> codes(rowBytes * static_cast<size_t>(texels.height));
        const bool cmyk = jpeg.out_color_space == JCS_CMYK;
        std::vector<uint8_t> cmykRow(cmyk ? 4 * static_cast<size_t>(texels.width) : 0);
        attempt([&] {
            jpeg_start_decompress(&jpeg);
            while (jpeg.output_scanline < jpeg.output_height) {
                uint8_t* row = codes.data() + rowBytes * jpeg.output_scanline;
                JSAMPROW target = cmyk ? cmykRow.data() : row;
                jpeg_read_scanlines(&jpeg, &target, 1);
                if (cmyk) cmykToRgb(cmykRow.data(), row, texels.width);
            }
            jpeg_finish_decompress(&jpeg);
        });
        const jpeg_error_mgr& manager = decompressor_.errors.manager;
        if (manager.num_warnings > 0) {
            const long more = manager.num_warnings - 1;
            warnings.push_back(name_ + ": damaged or truncated JPEG (libjpeg: " +
                               decompressor_.errors.firstWarning +
                               (more > 0 ? "; " + std::to_string(more) + " more warnings" : "") + ")");
        }
        return codes;
    }

private:
    // Runs libjpeg calls, turning its fatal error into strata::Error naming the file.
    template <typename Calls>
    void attempt(Calls calls) {
        try {
            calls();
        } catch (const std::runtime_error& e) {
            throw Error(name_ + ": cannot decode the texture (" + e.what() + ")");
        }
    }

    // Adobe's CMYK (and YCCK, which libjpeg turns into it) stores inverted inks: each colour
    // channel times K / 255 is the RGB value, rounded as stb_image rounds it.
    static void cmykToRgb(const uint8_t* cmyk, uint8_t* rgb, int width) {
        for (int x = 0; x < width; ++x, cmyk += 4, rgb += 3) {
            for (int c = 0; c < 3; ++c) {
                const unsigned product = unsigned{cmyk[c]} * cmyk[3] + 128u;
                rgb[c] = static_cast<uint8_t>((product + (product >> 8)) >> 8);
            }
        }
    }

    std::string name_;
    Decompressor decompressor_;
};

}  // namespace

TextureSize readJpegHeader(std::string_view bytes, const std::string& name) {
    return JpegDecoder(bytes, name).size();
}

std::vector<uint8_t> decodeJpeg(std::string_view bytes, const std::string& name,
                                std::vector<std::string>& warnings) {
    return JpegDecoder(bytes, name).decode(warnings);
}

}  // namespace strata
