#include "false_colour.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>

namespace strata::viewer {

glm::vec3 falseColour(float t) {
    static constexpr std::array<glm::vec3, 5> kRamp{
        glm::vec3(0.05f, 0.05f, 0.40f), glm::vec3(0.00f, 0.45f, 1.00f), glm::vec3(0.10f, 0.80f, 0.20f),
        glm::vec3(1.00f, 0.90f, 0.00f), glm::vec3(1.00f, 0.10f, 0.00f)};
    const float x = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(kRamp.size() - 1);
    const int i = std::min(static_cast<int>(std::floor(x)), static_cast<int>(kRamp.size()) - 2);
    return glm::mix(kRamp[i], kRamp[i + 1], x - static_cast<float>(i));
}

glm::vec3 adaptiveMaskColour(const glm::vec3& displayed, bool done) {
    return done ? glm::mix(displayed, glm::vec3(0.10f, 0.85f, 0.25f), kDoneWash) : displayed;
}

}  // namespace strata::viewer
