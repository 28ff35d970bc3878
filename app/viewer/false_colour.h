#pragma once
// The ramp of the viewer's error and sample-count views: t in [0, 1] (clamped) to a display colour,
// piecewise linear through five stops from dark blue to red. shaders/display.frag mirrors it; the
// tests compare the two.
#include <glm/vec3.hpp>

namespace strata::viewer {

glm::vec3 falseColour(float t);

// Colour of a pixel with no samples yet in the error and sample-count views.
inline constexpr float kNoSamplesGrey = 0.25f;

}  // namespace strata::viewer
