#include "scene/mtl_texture_statement.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <utility>

namespace strata {
namespace {

std::optional<float> number(std::string_view word) {
    float value = 0.0f;
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
    if (result.ec != std::errc() || result.ptr != word.data() + word.size()) return std::nullopt;
    return value;
}

// The MTL specification's options with a fixed number of arguments.
constexpr std::array<std::pair<std::string_view, int>, 10> kFixedOptions{{
    {"-blendu", 1}, {"-blendv", 1}, {"-bm", 1}, {"-boost", 1}, {"-cc", 1},
    {"-clamp", 1}, {"-imfchan", 1}, {"-mm", 2}, {"-texres", 1}, {"-type", 1},
}};

}  // namespace

bool isMtlTextureKey(std::string_view key) {
    return key == "map_Kd" || key == "map_Ke" || key == "map_d" || key == "norm" || key == "map_Bump" ||
           key == "bump" || key == "map_Pr" || key == "map_Pm";
}

std::optional<MtlTextureStatement> parseMtlTextureStatement(const std::vector<std::string_view>& words) {
    MtlTextureStatement statement;
    size_t i = 1;
    while (i < words.size() && words[i].size() > 1 && words[i].front() == '-') {
        const std::string_view option = words[i++];
        if (option == "-o" || option == "-s" || option == "-t") {
            glm::vec2 values = option == "-s" ? glm::vec2(1.0f) : glm::vec2(0.0f);
            for (int k = 0; k < 3 && i < words.size(); ++k) {
                const auto value = number(words[i]);
                if (!value) break;
                // from_chars reads "nan" and "inf": such a value is passed over, as w is.
                if (k < 2 && std::isfinite(*value)) values[k] = *value;
                ++i;
            }
            if (option == "-o") statement.offset = values;
            if (option == "-s") statement.scale = values;
            continue;
        }
        const auto fixed = std::find_if(kFixedOptions.begin(), kFixedOptions.end(),
                                        [&](const auto& known) { return known.first == option; });
        if (fixed == kFixedOptions.end()) {
            // Its arguments are taken to be the numbers after it (the file's name stays).
            if (statement.unknownOption.empty()) statement.unknownOption = std::string(option);
            while (i + 1 < words.size() && number(words[i])) ++i;
            continue;
        }
        const auto arguments = static_cast<size_t>(fixed->second);
        if (i + arguments > words.size()) return std::nullopt;
        if (option == "-bm") {
            // from_chars reads "nan" and "inf"; a multiplier must be a finite number.
            const auto value = number(words[i]);
            if (value && std::isfinite(*value)) statement.bumpMultiplier = *value;
        }
        if (option == "-imfchan" && words[i].size() == 1) statement.channel = words[i].front();
        if (option == "-clamp") statement.clamp = words[i] == "on";
        i += arguments;
    }
    if (i >= words.size()) return std::nullopt;
    const char* end = words.back().data() + words.back().size();
    statement.file = std::string(words[i].data(), end);
    std::replace(statement.file.begin(), statement.file.end(), '\\', '/');
    return statement;
}

std::string textureFileName(const std::string& mtlName, const std::string& file) {
    const std::filesystem::path name = std::filesystem::path(mtlName).parent_path() / file;
    return name.lexically_normal().generic_string();
}

}  // namespace strata
