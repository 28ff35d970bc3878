#include "io/tonemap.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "util/name_table.h"

namespace strata {
namespace {
constexpr NameTable<Tonemap, 3> kTonemaps{
    {{{"clamp", Tonemap::Clamp}, {"reinhard", Tonemap::Reinhard}, {"aces", Tonemap::Aces}}}};
}  // namespace

std::optional<Tonemap> parseTonemap(std::string_view name) { return kTonemaps.parse(name); }
std::string_view tonemapName(Tonemap tonemap) { return kTonemaps.name(tonemap); }
std::string tonemapNames() { return kTonemaps.joined(); }

glm::vec3 applyTonemap(const glm::vec3& linear, float exposure, Tonemap tonemap) {
    const glm::vec3 x = glm::max(linear, glm::vec3(0.0f)) * std::exp2(exposure);
    glm::vec3 mapped;
    switch (tonemap) {
        case Tonemap::Reinhard:
            mapped = x / (glm::vec3(1.0f) + x);
            break;
        case Tonemap::Aces:
            // Narkowicz's fit of the ACES filmic curve.
            mapped = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
            break;
        default:
            mapped = x;
            break;
    }
    return glm::clamp(mapped, glm::vec3(0.0f), glm::vec3(1.0f));
}

float encodeSrgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

uint8_t toByte(float encoded) {
    return static_cast<uint8_t>(std::lround(std::clamp(encoded, 0.0f, 1.0f) * 255.0f));
}

}  // namespace strata
