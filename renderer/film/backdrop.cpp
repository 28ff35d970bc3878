#include "film/backdrop.h"

#include <charconv>
#include <cmath>
#include <vector>
#include <glm/common.hpp>

namespace strata {
namespace {

// One radiance of "V" or "R,G,B": a finite number >= 0, the whole of `text`.
std::optional<float> radianceOf(std::string_view text) {
    float value = 0.0f;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    if (!(std::isfinite(value) && value >= 0.0f)) return std::nullopt;
    return value;
}

}  // namespace

std::optional<BackdropSetting> parseBackdrop(std::string_view text) {
    if (text == "env") return BackdropSetting{BackdropSetting::Kind::Environment};
    if (text == "gradient") return BackdropSetting{BackdropSetting::Kind::Gradient};
    std::vector<float> values;
    for (size_t start = 0;;) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const auto value = radianceOf(text.substr(start, comma - start));
        if (!value) return std::nullopt;
        values.push_back(*value);
        if (comma == text.size()) break;
        start = comma + 1;
    }
    if (values.size() == 1) return BackdropSetting{BackdropSetting::Kind::Colour, glm::vec3(values[0])};
    if (values.size() == 3) {
        return BackdropSetting{BackdropSetting::Kind::Colour, glm::vec3(values[0], values[1], values[2])};
    }
    return std::nullopt;
}

Backdrop::Backdrop(const BackdropSetting& setting, bool litByDefault)
    : kind_(setting.kind), colour_(setting.colour) {
    if (kind_ == BackdropSetting::Kind::Automatic) {
        kind_ = litByDefault ? BackdropSetting::Kind::Gradient : BackdropSetting::Kind::Environment;
    }
}

glm::vec3 Backdrop::radiance(float v) const {
    if (kind_ == BackdropSetting::Kind::Colour) return colour_;
    return glm::vec3(glm::mix(kGradientTop, kGradientBottom, glm::clamp(v, 0.0f, 1.0f)));
}

}  // namespace strata
