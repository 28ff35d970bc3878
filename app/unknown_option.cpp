#include "unknown_option.h"

#include <algorithm>
#include <CLI/App.hpp>

namespace strata {
namespace {

size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::optional<std::string> nearestOption(const std::string& name, const std::vector<std::string>& known) {
    std::vector<std::string> extending;
    for (const std::string& option : known) {
        if (option.rfind(name, 0) == 0) extending.push_back(option);
    }
    if (extending.size() == 1) return extending.front();
    std::optional<std::string> nearest;
    size_t best = 0;
    for (const std::string& option : known) {
        const size_t distance = editDistance(name, option);
        if (!nearest || distance < best) {
            nearest = option;
            best = distance;
        }
    }
    // A typo changes a character or two, or a third of a long name; beyond that the nearest name
    // is a guess.
    const size_t allowed = std::max<size_t>(2, (name.size() - 2) / 3);
    if (!nearest || best > allowed) return std::nullopt;
    return nearest;
}

std::optional<std::string> unknownOptionMessage(const CLI::App& command, const std::vector<std::string>& arguments) {
    std::vector<std::string> known;
    for (const CLI::Option* option : command.get_options()) {
        for (const std::string& name : option->get_lnames()) known.push_back("--" + name);
    }
    for (const std::string& argument : arguments) {
        if (argument == "--") break;
        if (argument.size() < 3 || argument.rfind("--", 0) != 0) continue;
        const std::string name = argument.substr(0, argument.find('='));
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        const auto nearest = nearestOption(name, known);
        return "unknown option '" + name + "'" + (nearest ? " (did you mean " + *nearest + "?)" : "");
    }
    return std::nullopt;
}

}  // namespace strata
