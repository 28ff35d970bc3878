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

// The programs' display (the viewer, and `strata render`'s PNG): Narkowicz's fit of the ACES
// filmic curve, x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), which lifts the shadows a little and
// rolls the highlights off (to 1 at x = 7.2) where the clamp would cut them, at the exposure of
// io/auto_exposure.h unless one is given. Clamp is the linear radiance as it is, cut at 1.
inline constexpr Tonemap kDefaultTonemap = Tonemap::Aces;

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
