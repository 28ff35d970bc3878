#include "scene/scene_folder.h"

#include <algorithm>
#include <system_error>

#include "util/error.h"
#include "util/printable.h"
#include "util/text_file.h"

namespace strata {
namespace {

// Whether `path` is `folder` or lies below it; both canonical.
bool isInside(const std::filesystem::path& path, const std::filesystem::path& folder) {
    return std::mismatch(folder.begin(), folder.end(), path.begin(), path.end()).first == folder.end();
}

}  // namespace

SceneFolder::SceneFolder(const std::filesystem::path& mainFile, const SceneReadOptions& options)
    : options_(options) {
    std::error_code error;
    folder_ = std::filesystem::weakly_canonical(std::filesystem::absolute(mainFile.parent_path(), error),
                                                error);
    if (error) throw Error(printable(mainFile.string()) + ": cannot resolve the scene's folder");
}

std::optional<std::string> SceneFolder::read(const std::string& reference, const std::string& where) {
    const std::string named = where + " " + quote(reference);
    // The system would read the name only up to the NUL: another file than the one checked.
    if (reference.find('\0') != std::string::npos) {
        throw Error(named + " holds a NUL byte, which no file name does");
    }
    // The path read is the resolved one: what was checked is what is opened.
    std::error_code error;
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(folder_ / reference, error);
    if (error) throw Error(named + " cannot be read");
    const bool inside = isInside(resolved, folder_);
    const std::string folder = " the model's folder (" + printable(folder_.string()) + ")";
    if (!inside && !options_.allowOutsideFiles) {
        throw Error(named + " resolves outside" + folder + "; --allow-outside-files reads it");
    }
    std::string bytes;
    switch (readRegularFile(resolved, bytes)) {
        case FileKind::Regular: break;
        case FileKind::Missing: return std::nullopt;
        case FileKind::NotRegular: throw Error(named + " is not a regular file");
        case FileKind::Unreadable: throw Error(named + " cannot be read");
    }
    const std::string note = named + " is outside" + folder + "; read as --allow-outside-files allows";
    if (!inside && std::find(outsideNotes_.begin(), outsideNotes_.end(), note) == outsideNotes_.end()) {
        outsideNotes_.push_back(note);
    }
    return bytes;
}

std::string SceneFolder::require(const std::string& reference, const std::string& where) {
    std::optional<std::string> bytes = read(reference, where);
    if (!bytes) throw Error(where + " " + quote(reference) + ": no such file");
    return std::move(*bytes);
}

}  // namespace strata
