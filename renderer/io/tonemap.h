#pragma once
// Display transforms from linear radiance to 8-bit sRGB. The viewer's display shader implements
// the same functions in GLSL; its tests compare against these.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <glm/vec3.hpp>

namespace strata {

enum class Tonemap { Clamp, Reinhard, Aces };

std::optional<Tonemap> parseTonemap(std::string_view name);
std::string_view tonemapName(Tonemap tonemap);
// "clamp|reinhard|aces", for option help and error messages.
std::string tonemapNames();

// exposure is in stops: the radiance is scaled by 2^exposure before the curve.
glm::vec3 applyTonemap(const glm::vec3& linear, float exposure, Tonemap tonemap);
// IEC 61966-2-1 sRGB encoding of a value in [0, 1].
float encodeSrgb(float linear);
uint8_t toByte(float encoded);

}  // namespace strata
