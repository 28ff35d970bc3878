#include "io/exr_header.h"

#include <algorithm>
#include <cstring>
#include <openexr.h>

#include "io/image_io.h"
#include "util/error.h"

namespace strata {

bool isExr(std::string_view bytes) { return bytes.size() >= 4 && std::memcmp(bytes.data(), "\x76\x2f\x31\x01", 4) == 0; }

namespace {

// The file's bytes as OpenEXR's core reads them, and the first message it gave.
struct ExrBytes {
    std::string_view bytes;
    std::string firstError;
};

int64_t readBytes(exr_const_context_t, void* user, void* buffer, uint64_t size, uint64_t offset,
                  exr_stream_error_func_ptr_t) {
    const std::string_view bytes = static_cast<ExrBytes*>(user)->bytes;
    if (offset >= bytes.size()) return 0;
    const uint64_t count = std::min<uint64_t>(size, bytes.size() - offset);
    std::memcpy(buffer, bytes.data() + offset, count);
    return static_cast<int64_t>(count);
}

int64_t sizeOfBytes(exr_const_context_t, void* user) {
    return static_cast<int64_t>(static_cast<ExrBytes*>(user)->bytes.size());
}

// Keeps OpenEXR's first message for ours (it would print every one to stderr).
void keepFirstError(exr_const_context_t context, exr_result_t, const char* message) {
    void* user = nullptr;
    if (exr_get_user_data(context, &user) != EXR_ERR_SUCCESS || !user) return;
    std::string& first = static_cast<ExrBytes*>(user)->firstError;
    if (first.empty() && message) first = message;
}

// A reading context of the core library, finished on every way out.
class ExrContext {
public:
    ExrContext(ExrBytes& bytes, const std::string& name) {
        exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
        init.user_data = &bytes;
        init.read_fn = readBytes;
        init.size_fn = sizeOfBytes;
        init.error_handler_fn = keepFirstError;
        result_ = exr_start_read(&context_, name.c_str(), &init);
    }
    ExrContext(const ExrContext&) = delete;
    ExrContext& operator=(const ExrContext&) = delete;
    ~ExrContext() {
        if (result_ == EXR_ERR_SUCCESS) exr_finish(&context_);
    }
    exr_result_t result() const { return result_; }
    exr_const_context_t get() const { return context_; }

private:
    exr_context_t context_ = nullptr;
    exr_result_t result_;
};

// The file offset and recorded size of each full-resolution chunk of part 0 lie within the
// file; returns the index of the first chunk that does not, or -1.
int firstMissingChunk(exr_const_context_t context, exr_storage_t storage, const exr_attr_box2i_t& window,
                      uint64_t fileBytes) {
    const auto holds = [&](exr_result_t result, const exr_chunk_info_t& chunk) {
        return result == EXR_ERR_SUCCESS && chunk.data_offset <= fileBytes &&
               chunk.packed_size <= fileBytes - chunk.data_offset;
    };
    int index = 0;
    exr_chunk_info_t chunk{};
    if (storage == EXR_STORAGE_SCANLINE) {
        int32_t lines = 0;
        if (exr_get_scanlines_per_chunk(context, 0, &lines) != EXR_ERR_SUCCESS || lines < 1) return 0;
        for (int64_t y = window.min.y; y <= window.max.y; y += lines, ++index) {
            const exr_result_t read = exr_read_scanline_chunk_info(context, 0, static_cast<int>(y), &chunk);
            if (!holds(read, chunk)) return index;
        }
        return -1;
    }
    int32_t tileWidth = 0, tileHeight = 0, levelWidth = 0, levelHeight = 0;
    if (exr_get_tile_sizes(context, 0, 0, 0, &tileWidth, &tileHeight) != EXR_ERR_SUCCESS ||
        exr_get_level_sizes(context, 0, 0, 0, &levelWidth, &levelHeight) != EXR_ERR_SUCCESS ||
        tileWidth < 1 || tileHeight < 1) {
        return 0;
    }
    for (int ty = 0; static_cast<int64_t>(ty) * tileHeight < levelHeight; ++ty) {
        for (int tx = 0; static_cast<int64_t>(tx) * tileWidth < levelWidth; ++tx, ++index) {
            if (!holds(exr_read_tile_chunk_info(context, 0, tx, ty, 0, 0, &chunk), chunk)) return index;
        }
    }
    return -1;
}

}  // namespace

TextureSize readExrHeader(std::string_view bytes, const std::string& name) {
    ExrBytes file{bytes, {}};
    const ExrContext context(file, name);
    const auto unreadable = [&](const std::string& reason) {
        return Error(name + ": not a readable EXR file (" + reason + ")");
    };
    const auto libraryReason = [&](const char* otherwise) {
        return file.firstError.empty() ? std::string(otherwise) : file.firstError;
    };
    if (context.result() != EXR_ERR_SUCCESS) {
        throw unreadable(libraryReason(exr_get_default_error_message(context.result())));
    }
    exr_storage_t storage{};
    exr_attr_box2i_t window{};
    int32_t chunks = 0;
    if (exr_get_storage(context.get(), 0, &storage) != EXR_ERR_SUCCESS ||
        exr_get_data_window(context.get(), 0, &window) != EXR_ERR_SUCCESS ||
        exr_get_chunk_count(context.get(), 0, &chunks) != EXR_ERR_SUCCESS) {
        throw unreadable(libraryReason("no image part"));
    }
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED) {
        throw unreadable("deep images are not read");
    }
    const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
    const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
    requirePlausibleImageSize(width, height, bytes.size(), name);
    const int missing = firstMissingChunk(context.get(), storage, window, bytes.size());
    if (missing >= 0) {
        throw unreadable(std::to_string(width) + " x " + std::to_string(height) + " pixels, but chunk " +
                         std::to_string(missing + 1) + " of " + std::to_string(chunks) +
                         " of their data lies outside the file's " + std::to_string(bytes.size()) +
                         " bytes: truncated or corrupt");
    }
    return {static_cast<int>(width), static_cast<int>(height), 3, 4};
}

}  // namespace strata
