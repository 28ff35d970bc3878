#pragma once
// The ramp of the viewer's error and sample-count views: t in [0, 1] (clamped) to a display colour,
// piecewise linear through five stops from dark blue to red, and the adaptive-mask view's wash.
// shaders/display.frag mirrors both; the tests compare the two.
#include <glm/vec3.hpp>

namespace strata::viewer {

glm::vec3 falseColour(float t);

// Colour of a pixel with no samples yet in the error and sample-count views.
inline constexpr float kNoSamplesGrey = 0.25f;

// The adaptive-mask view: a pixel that adaptive sampling has finished is the displayed (sRGB)
// colour washed with green, so the image stays legible; a pixel still sampled keeps its colour.
inline constexpr float kDoneWash = 0.65f;
glm::vec3 adaptiveMaskColour(const glm::vec3& displayed, bool done);

}  // namespace strata::viewer
