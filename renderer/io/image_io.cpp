#include "io/image_io.h"

#include <algorithm>
#include <cctype>
#include <exception>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfThreading.h>
#include <stb_image_write.h>
#include <tbb/info.h>

#include "io/exr_header.h"
#include "io/output_file.h"
#include "util/text_file.h"
#include "util/error.h"

namespace strata {
namespace {

// The output file as OpenEXR's output stream: OpenEXR writes through it, never opening the
// target's name itself.
class OutputFileStream final : public Imf::OStream {
public:
    explicit OutputFileStream(OutputFile& file) : Imf::OStream(file.target().c_str()), file_(file) {}
    void write(const char c[], int n) override { file_.write(c, static_cast<size_t>(n)); }
    uint64_t tellp() override { return file_.position(); }
    void seekp(uint64_t position) override { file_.seek(position); }

private:
    OutputFile& file_;
};

void writeExr(OutputFile& file, const Image& image) {
    Imf::Header header(image.width, image.height);
    for (const char* channel : {"R", "G", "B"}) header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
    const bool hasAlpha = !image.alpha.empty();
    if (hasAlpha) header.channels().insert("A", Imf::Channel(Imf::FLOAT));
    OutputFileStream stream(file);
    Imf::OutputFile out(stream, header);
    Imf::FrameBuffer frame;
    const size_t xStride = sizeof(glm::vec3);
    const size_t yStride = xStride * image.width;
    char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
    frame.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
    frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
    frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
    if (hasAlpha) {
        char* alpha = const_cast<char*>(reinterpret_cast<const char*>(image.alpha.data()));
        frame.insert("A", Imf::Slice(Imf::FLOAT, alpha, sizeof(float), sizeof(float) * image.width));
    }
    out.setFrameBuffer(frame);
    out.writePixels(image.height);
}

void writePfm(OutputFile& file, const Image& image) {
    // PFM: "PF", size, scale (negative = little-endian), then rows bottom to top.
    file.write("PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n");
    for (int y = image.height - 1; y >= 0; --y) {
        file.write(&image.pixels[static_cast<size_t>(y) * image.width], sizeof(glm::vec3) * image.width);
    }
}

// 8-bit RGB rows, top first, as PNG; stb hands the encoded file to a callback, which cannot throw
// through stb's C code, so a failure is kept and rethrown after.
void writeRgb8(OutputFile& file, int width, int height, const uint8_t* rgb) {
    struct Sink {
        OutputFile& file;
        std::exception_ptr failure;
    } sink{file, nullptr};
    const auto toFile = [](void* context, void* data, int size) {
        auto& to = *static_cast<Sink*>(context);
        if (to.failure) return;
        try {
            to.file.write(data, static_cast<size_t>(size));
        } catch (...) {
            to.failure = std::current_exception();
        }
    };
    const int encoded = stbi_write_png_to_func(toFile, &sink, width, height, 3, rgb, width * 3);
    if (sink.failure) std::rethrow_exception(sink.failure);
    if (!encoded) throw Error(file.target().string() + ": cannot write: PNG encoder failed");
}

void writePng(OutputFile& file, const Image& image, const PngSettings& settings) {
    std::vector<uint8_t> bytes(image.pixels.size() * 3);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::vec3 mapped = applyTonemap(image.pixels[i], settings.exposure, settings.tonemap);
        for (int c = 0; c < 3; ++c) bytes[3 * i + c] = toByte(encodeSrgb(mapped[c]));
    }
    writeRgb8(file, image.width, image.height, bytes.data());
}

// An EXR file's bytes as OpenEXR's input stream, so that a bundle's copy decodes without a file.
class MemoryStream final : public Imf::IStream {
public:
    MemoryStream(std::string_view bytes, const std::string& name) : Imf::IStream(name.c_str()), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || static_cast<uint64_t>(n) > bytes_.size() - position_) {
            throw std::runtime_error("unexpected end of file");
        }
        std::copy_n(bytes_.data() + position_, n, c);
        position_ += static_cast<uint64_t>(n);
        return position_ < bytes_.size();
    }
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t position) override { position_ = std::min<uint64_t>(position, bytes_.size()); }

private:
    std::string_view bytes_;
    uint64_t position_ = 0;
};

}  // namespace

ImageFormat imageFormatOf(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".exr") return ImageFormat::Exr;
    if (extension == ".pfm") return ImageFormat::Pfm;
    if (extension == ".png") return ImageFormat::Png;
    throw Error(path.string() + ": unknown image format (use .exr, .pfm or .png)");
}

void writeImage(OutputFile& file, const Image& image, const PngSettings& png) {
    const ImageFormat format = imageFormatOf(file.target());
    try {
        switch (format) {
            case ImageFormat::Exr: writeExr(file, image); break;
            case ImageFormat::Pfm: writePfm(file, image); break;
            case ImageFormat::Png: writePng(file, image, png); break;
        }
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {  // OpenEXR's
        throw Error(file.target().string() + ": cannot write: " + e.what());
    }
}

void writeImage(const std::filesystem::path& path, const Image& image, const PngSettings& png) {
    imageFormatOf(path);  // an unknown extension fails before a temporary is made
    OutputFile file(path);
    writeImage(file, image, png);
    file.commit();
}

void writeRgb8Png(const std::filesystem::path& path, int width, int height,
                  const std::vector<uint8_t>& rgb) {
    if (imageFormatOf(path) != ImageFormat::Png) throw Error(path.string() + ": must be a .png file");
    if (width < 1 || height < 1 || rgb.size() != static_cast<size_t>(width) * height * 3) {
        throw Error(path.string() + ": image size does not match its pixels");
    }
    OutputFile file(path);
    writeRgb8(file, width, height, rgb.data());
    file.commit();
}

void requirePlausibleImageSize(long long width, long long height, size_t fileBytes, const std::string& name,
                               long long maxPixelsPerByte) {
    constexpr long long kMaxPixels = 1LL << 28;
    const std::string size = std::to_string(width) + " x " + std::to_string(height);
    if (width < 1 || height < 1 || width > kMaxPixels / height) {
        throw Error(name + ": unreasonable image size " + size);
    }
    const auto leastBytes = static_cast<size_t>((width * height + maxPixelsPerByte - 1) / maxPixelsPerByte);
    if (fileBytes < leastBytes) {
        throw Error(name + ": a " + size + " image cannot be stored in " + std::to_string(fileBytes) +
                    " bytes (truncated or corrupt)");
    }
}

void setExrThreads(int threads) {
    const int count = threads > 0 ? threads : tbb::info::default_concurrency();
    // A pool of one thread would only hand the work from the caller to it.
    Imf::setGlobalThreadCount(count > 1 ? count : 0);
}

Image readExr(const std::filesystem::path& path) { return readExr(readExrFile(path), path.string()); }

std::string readExrFile(const std::filesystem::path& path) {
    if (!std::filesystem::is_regular_file(path)) throw Error(path.string() + ": no such EXR file");
    return readTextFile(path, "EXR file");
}

Image readExr(std::string_view bytes, const std::string& name) {
    try {
        const TextureSize size = readExrHeader(bytes, name);
        MemoryStream stream(bytes, name);
        Imf::InputFile in(stream);
        const Imath::Box2i window = in.header().dataWindow();
        Image image;
        image.width = window.max.x - window.min.x + 1;
        image.height = window.max.y - window.min.y + 1;
        // The one header, read twice: a disagreement would be a library's fault, not the file's.
        if (image.width != size.width || image.height != size.height) {
            throw Error(name + ": not a readable EXR file (its data window reads two ways)");
        }
        for (const char* channel : {"R", "G", "B"}) {
            if (!in.header().channels().findChannel(channel)) {
                throw Error(name + ": no " + channel + " channel");
            }
        }
        image.pixels.resize(static_cast<size_t>(image.width) * image.height);
        // OpenEXR addresses the buffer by absolute pixel coordinates; Slice::Make shifts the base
        // by the data window's origin in integer arithmetic (a shifted pointer would leave the
        // array, which C++ does not allow even before it is dereferenced).
        const auto* pixels = reinterpret_cast<const char*>(image.pixels.data());
        const size_t xStride = sizeof(glm::vec3);
        const size_t yStride = xStride * image.width;
        Imf::FrameBuffer frame;
        frame.insert("R", Imf::Slice::Make(Imf::FLOAT, pixels, window, xStride, yStride));
        frame.insert("G", Imf::Slice::Make(Imf::FLOAT, pixels + sizeof(float), window, xStride, yStride));
        frame.insert("B", Imf::Slice::Make(Imf::FLOAT, pixels + 2 * sizeof(float), window, xStride, yStride));
        if (in.header().channels().findChannel("A")) {
            image.alpha.resize(image.pixels.size());
            frame.insert("A", Imf::Slice::Make(Imf::FLOAT, image.alpha.data(), window, sizeof(float),
                                               sizeof(float) * image.width));
        }
        in.setFrameBuffer(frame);
        in.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(name + ": not a readable EXR file (" + e.what() + ")");
    }
}

}  // namespace strata
