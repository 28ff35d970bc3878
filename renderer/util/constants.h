#pragma once

namespace strata {

inline constexpr float kPi = 3.14159265358979323846f;

}  // namespace strata
