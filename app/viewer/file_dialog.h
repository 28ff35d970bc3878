#pragma once
// A small file chooser drawn with Dear ImGui, which has none (nor does Debian package one): the
// folder's subfolders and its files of the wanted extensions, a way up and into folders, and a
// path field. The panel opens it to pick a scene, an environment map or a reference image.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "control_rects.h"

namespace strata::viewer {

struct FolderEntry {
    std::string name;
    bool folder = false;
    bool operator==(const FolderEntry&) const = default;
};

// What a chooser lists of `folder`: its subfolders, then its files whose extension is, in any
// case, one of `extensions` (lower case, with the dot), each group sorted by name; hidden entries
// (a leading '.') are left out. Throws strata::Error naming the folder when it cannot be read.
std::vector<FolderEntry> listFolder(const std::filesystem::path& folder,
                                    const std::vector<std::string>& extensions);

class FileDialog {
public:
    // Shows the dialog from the next draw, titled `title`, listing `start` when it is a folder,
    // else the folder of the file it names (that file's name in the path field), else the
    // nearest folder above it that exists, else the current one.
    void open(std::string title, const std::filesystem::path& start, std::vector<std::string> extensions);
    bool isOpen() const { return open_; }
    // Draws the dialog (modal, over the whole window) while it is open; returns the file chosen,
    // once, as the dialog closes. A click on an entry puts its name in the path field; a double
    // click on a folder, or Enter or the Open button with a folder in the field, enters it; the
    // same with a file chooses it. Names its controls in `controls`: "dialog path", "dialog
    // open", "dialog cancel" and "dialog/NAME" for each entry, ".." too.
    std::optional<std::filesystem::path> draw(ControlRects& controls);

    const std::filesystem::path& folder() const { return folder_; }
    const std::vector<FolderEntry>& entries() const { return entries_; }
    // Lists `folder` (absolute, normalised); on failure the list is empty and says why.
    void enter(const std::filesystem::path& folder);

private:
    // The path field's text, relative to the folder listed unless absolute.
    std::filesystem::path typedPath() const;
    void setField(const std::string& text);
    // What Enter, the Open button or a double click does with `path`: enters a folder, else
    // closes the dialog and returns the file.
    std::optional<std::filesystem::path> accept(const std::filesystem::path& path);

    bool open_ = false;
    bool opening_ = false;  // ImGui's popup is opened on the first draw after open()
    std::string title_;
    std::vector<std::string> extensions_;
    std::filesystem::path folder_;
    std::vector<FolderEntry> entries_;
    std::string error_;
    std::array<char, 1024> field_{};
};

}  // namespace strata::viewer
