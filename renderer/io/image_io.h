#pragma once
// Images on disk. EXR (OpenEXR, 32-bit float) and PFM hold linear radiance; PNG (stb) is
// tonemapped sRGB. An EXR also holds the image's alpha, when it has one, as its A channel: a
// render's coverage, the share of each pixel's camera rays that found a surface. Its RGB is the
// radiance as rendered, the backdrop (film/backdrop.h) included where A < 1, so it is premultiplied
// by A only over a black backdrop. Every write goes through an OutputFile (io/output_file.h): to a
// temporary file created exclusively beside the target, renamed over it only when complete.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>
#include <glm/vec3.hpp>

#include "io/tonemap.h"

namespace strata {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels;  // row-major, top row first, linear RGB
    std::vector<float> alpha{};     // the same order, or empty: none
};

struct PngSettings {
    float exposure = 0.0f;
    Tonemap tonemap = Tonemap::Clamp;
};

class OutputFile;

enum class ImageFormat { Exr, Pfm, Png };
// The format named by the path's extension, in any letter case; throws strata::Error
// "PATH: unknown image format (use .exr, .pfm or .png)" for any other.
ImageFormat imageFormatOf(const std::filesystem::path& path);

void writeImage(const std::filesystem::path& path, const Image& image, const PngSettings& png = {});
// Encodes `image` into `file` in the format of its target's extension, leaving the commit to the
// caller (who may first encode the other files of one result, so that all or none replace theirs).
void writeImage(OutputFile& file, const Image& image, const PngSettings& png = {});
// Writes already display-encoded 8-bit RGB (top row first) as PNG, e.g. a screenshot of the viewer.
void writeRgb8Png(const std::filesystem::path& path, int width, int height,
                  const std::vector<uint8_t>& rgb);
// The densest coding any reader here decodes without a tighter bound of its own: a 1-bit PNG at
// deflate's best ratio (1032:1), 8256 pixels a byte.
inline constexpr long long kDensestPixelsPerByte = 8 * 1032;
// Throws strata::Error "NAME: ..." unless a width x height image could be held in `fileBytes`
// bytes: at most 2^28 pixels (16k x 16k), and no more than `maxPixelsPerByte`, the densest coding
// of the file's format, allows. A forged or truncated header then fails at once instead of
// allocating for pixels the file does not hold.
void requirePlausibleImageSize(long long width, long long height, size_t fileBytes, const std::string& name,
                               long long maxPixelsPerByte = kDensestPixelsPerByte);
// OpenEXR compresses and decompresses an EXR's blocks of lines on a pool of threads that is the
// process's own (OpenEXR's global pool). This sizes it for a command's --threads: `threads`
// threads, 0 for one per core the process may use; with 1 (and until called) the calling thread
// does the work alone. The bytes written and the pixels read are the same for any count.
void setExrThreads(int threads);
// Reads the R, G, B (and A, when there is one) channels of an EXR file as linear float; throws
// strata::Error naming the file, before anything is allocated for a header the file does not hold
// the pixels of (readExrHeader).
Image readExr(const std::filesystem::path& path);
// The bytes of an EXR file, undecoded; throws strata::Error "PATH: no such EXR file" or
// "PATH: cannot open EXR file".
std::string readExrFile(const std::filesystem::path& path);
// The same from an EXR file's bytes, as a scene bundle carries them; `name` stands for the file
// in messages.
Image readExr(std::string_view bytes, const std::string& name);

}  // namespace strata
