#pragma once
// A fixed table of (name, enum value) pairs: how options such as --sampler and --tonemap are
// parsed, printed and listed in help, from one place per enum.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace strata {

template <typename Enum, size_t Size>
struct NameTable {
    std::array<std::pair<std::string_view, Enum>, Size> entries;

    std::optional<Enum> parse(std::string_view name) const {
        for (const auto& [entryName, value] : entries) {
            if (entryName == name) return value;
        }
        return std::nullopt;
    }
    std::string_view name(Enum value) const {
        for (const auto& [entryName, entryValue] : entries) {
            if (entryValue == value) return entryName;
        }
        return "unknown";
    }
    // "a|b|c"
    std::string joined() const {
        std::string names;
        for (const auto& entry : entries) {
            if (!names.empty()) names += '|';
            names += entry.first;
        }
        return names;
    }
};

}  // namespace strata
