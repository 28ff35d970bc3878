#include "usage.h"

#include <CLI/App.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>

#include "io/output_file.h"
#include "util/error.h"

namespace strata {
namespace {

// The optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// adjacent characters, one each (a swap is the commonest typing slip; Levenshtein counts it as 2).
size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t substitution = d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[a.size()][b.size()];
}

std::string withoutDashes(const std::string& name) { return name.substr(name.find_first_not_of('-')); }

// "-x" or "--xyz", but not a negative number.
bool looksLikeOption(const std::string& argument) {
    return argument.size() > 1 && argument[0] == '-' &&
           !std::isdigit(static_cast<unsigned char>(argument[1])) && argument[1] != '.';
}

// Every name `command` takes an option by, with its dashes.
std::vector<std::string> optionNames(const CLI::App& command) {
    std::vector<std::string> names;
    for (const CLI::Option* option : command.get_options()) {
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
        for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
    return names;
}

}  // namespace

std::optional<std::string> nearestName(const std::string& typed, const std::vector<std::string>& known) {
    const std::string core = typed.substr(0, typed.find('='));  // --spp=24 names --spp
    if (core.find_first_not_of('-') == std::string::npos) return std::nullopt;
    std::vector<std::string> extending;
    for (const std::string& name : known) {
        if (name.size() > core.size() && name.compare(0, core.size(), core) == 0) extending.push_back(name);
    }
    if (extending.size() == 1 && withoutDashes(core).size() >= 2) return extending.front();
    const std::string* nearest = nullptr;
    size_t nearestDistance = 0;
    for (const std::string& name : known) {
        const size_t distance = editDistance(core, name);
        if (!nearest || distance < nearestDistance) {
            nearest = &name;
            nearestDistance = distance;
        }
    }
    const size_t nearEnough = std::max<size_t>(1, (withoutDashes(core).size() + 1) / 3);
    if (!nearest || nearestDistance > nearEnough) return std::nullopt;
    return *nearest;
}

std::string describeParseError(const CLI::App& app, const CLI::ParseError& error) {
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    const CLI::App* command = parsed.empty() ? &app : parsed.front();
    const std::string help = "(see " + std::string(command == &app ? "" : app.get_name() + " ") +
                             command->get_name() + " --help)";
    if (!dynamic_cast<const CLI::ExtrasError*>(&error)) return std::string(error.what()) + " " + help;
    std::vector<std::string> extras = command->remaining();
    if (extras.empty()) extras = app.remaining(true);
    if (extras.empty()) return std::string(error.what()) + " " + help;
    const auto option = std::find_if(extras.begin(), extras.end(), looksLikeOption);
    if (option == extras.end()) return "unexpected argument '" + extras.front() + "' " + help;
    std::string message = "unknown option '" + *option + "'";
    if (const auto nearest = nearestName(*option, optionNames(*command))) {
        message += "; did you mean '" + *nearest + "'?";
    }
    return message + " " + help;
}

void acceptUnsigned64(CLI::Option& option) {
    option.check(CLI::Validator(
        [](const std::string& text) {
            uint64_t value = 0;
            const char* end = text.data() + text.size();
            const auto [stop, error] = std::from_chars(text.data(), end, value);
            const bool whole = !text.empty() && error == std::errc() && stop == end;
            return whole ? std::string() : "must be a whole number from 0 to 18446744073709551615";
        },
        ""));
}

ImageFormat checkOutputOption(const std::string& option, const std::filesystem::path& path,
                              bool probe) {
    // A folder in the way is named as such, whatever its name's extension.
    if (probe && std::filesystem::is_directory(path)) {
        throw Error(option + ": " + path.string() + ": cannot write: it is a folder");
    }
    ImageFormat format{};
    try {
        format = imageFormatOf(path);
    } catch (const Error& e) {
        throw UsageError(option + ": " + e.what());
    }
    if (!probe) return format;
    try {
        requireWritable(path);
    } catch (const Error& e) {
        throw Error(option + ": " + e.what());
    }
    return format;
}

}  // namespace strata
