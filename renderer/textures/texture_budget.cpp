#include "textures/texture_budget.h"

#include <cstdio>
#include <iterator>

#include "util/error.h"

namespace strata {

void TextureBudget::reserve(const TextureSize& size, const std::string& what) {
    const uint64_t bytes = size.bytes();
    if (used_ + bytes <= limit_) {
        used_ += bytes;
        return;
    }
    char line[256];
    std::snprintf(line, sizeof line,
                  " is %d x %d, %d channel%s of %d bits (%s); with it the scene's textures would take %s, "
                  "over the --texture-budget of %s",
                  size.width, size.height, size.channels, size.channels == 1 ? "" : "s",
                  8 * size.bytesPerChannel, describeBytes(bytes).c_str(), describeBytes(used_ + bytes).c_str(),
                  describeBytes(limit_).c_str());
    throw Error(what + line);
}

std::string describeBytes(uint64_t bytes) {
    static const char* const units[] = {"KiB", "MiB", "GiB", "TiB"};
    if (bytes < 1024) return std::to_string(bytes) + " bytes";
    double value = static_cast<double>(bytes) / 1024.0;
    size_t unit = 0;
    while (value >= 1024.0 && unit + 1 < std::size(units)) {
        value /= 1024.0;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %s", value, units[unit]);
    return text;
}

}  // namespace strata
