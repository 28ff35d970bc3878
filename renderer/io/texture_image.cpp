#include "io/texture_image.h"

#include <cstring>
#include <memory>
#include <vector>
#include <stb_image.h>

#include "io/image_io.h"
#include "util/error.h"

namespace strata {
namespace {

bool isExr(std::string_view bytes) { return bytes.size() >= 4 && std::memcmp(bytes.data(), "\x76\x2f\x31\x01", 4) == 0; }

Texture decodeExr(std::string_view bytes, const std::string& name) {
    const Image image = readExr(bytes, name);
    std::vector<float> texels;
    texels.reserve(image.pixels.size() * 3);
    for (const glm::vec3& p : image.pixels) texels.insert(texels.end(), {p.x, p.y, p.z});
    return Texture(image.width, image.height, 3, std::move(texels));
}

}  // namespace

Texture decodeTexture(std::string_view bytes, const std::string& name, TextureEncoding encoding) {
    const auto fail = [&](const std::string& reason) -> Error {
        return Error(name + ": cannot decode the texture (" + reason + ")");
    };
    // readExr's messages name the file already.
    if (isExr(bytes)) return decodeExr(bytes, name);
    if (bytes.empty()) throw fail("the file is empty");
    if (bytes.size() > static_cast<size_t>(INT32_MAX)) throw fail("larger than 2 GB");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = static_cast<int>(bytes.size());
    if (stbi_is_hdr_from_memory(data, size)) throw fail("Radiance HDR textures are not read; use EXR");
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, size, &width, &height, &channels)) throw fail(stbi_failure_reason());
    requirePlausibleImageSize(width, height, bytes.size(), name);
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(data, size, &width, &height, &channels, 0), stbi_image_free);
    if (!pixels) throw fail(stbi_failure_reason());
    const size_t codes = static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(channels);
    return Texture(width, height, channels, std::vector<uint8_t>(pixels.get(), pixels.get() + codes), encoding);
}

}  // namespace strata
