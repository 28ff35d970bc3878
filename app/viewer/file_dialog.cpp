#include "file_dialog.h"

#include <algorithm>
#include <cstdio>
#include <system_error>
#include <utility>

#include "scene/scene_format.h"
#include "util/error.h"

namespace strata::viewer {
namespace {

// The folder a dialog opened at `start` lists (see FileDialog::open).
std::filesystem::path startingFolder(const std::filesystem::path& start) {
    std::error_code error;
    std::filesystem::path folder = std::filesystem::absolute(start.empty() ? "." : start, error);
    while (!folder.empty() && !std::filesystem::is_directory(folder, error)) {
        if (folder == folder.parent_path()) break;
        folder = folder.parent_path();
    }
    if (!std::filesystem::is_directory(folder, error)) folder = std::filesystem::current_path(error);
    return folder;
}

}  // namespace

std::vector<FolderEntry> listFolder(const std::filesystem::path& folder,
                                    const std::vector<std::string>& extensions) {
    std::error_code error;
    std::filesystem::directory_iterator it(folder, error);
    if (error) throw Error(folder.string() + ": cannot list the folder (" + error.message() + ")");
    std::vector<FolderEntry> folders, files;
    for (; it != std::filesystem::directory_iterator(); it.increment(error)) {
        if (error) throw Error(folder.string() + ": cannot list the folder (" + error.message() + ")");
        const std::string name = it->path().filename().string();
        if (name.empty() || name.front() == '.') continue;
        std::error_code statError;  // a dangling link or an unreadable entry: not listed
        if (it->is_directory(statError)) {
            folders.push_back({name, true});
        } else if (it->is_regular_file(statError) &&
                   std::count(extensions.begin(), extensions.end(), lowerCaseExtension(it->path()))) {
            files.push_back({name, false});
        }
    }
    const auto byName = [](const FolderEntry& a, const FolderEntry& b) { return a.name < b.name; };
    std::sort(folders.begin(), folders.end(), byName);
    std::sort(files.begin(), files.end(), byName);
    folders.insert(folders.end(), files.begin(), files.end());
    return folders;
}

void FileDialog::open(std::string title, const std::filesystem::path& start,
                      std::vector<std::string> extensions) {
    title_ = std::move(title);
    extensions_ = std::move(extensions);
    const std::filesystem::path folder = startingFolder(start);
    enter(folder);
    std::error_code error;
    const bool namesFile = !start.empty() && std::filesystem::is_regular_file(start, error) &&
                           std::filesystem::absolute(start, error).parent_path() == folder_;
    setField(namesFile ? start.filename().string() : "");
    open_ = true;
    opening_ = true;
}

void FileDialog::enter(const std::filesystem::path& folder) {
    std::error_code error;
    folder_ = std::filesystem::absolute(folder, error).lexically_normal();
    // "a/b/" normalises to "a/b/": the folder is named without its trailing separator.
    if (folder_.has_relative_path() && folder_.filename().empty()) folder_ = folder_.parent_path();
    error_.clear();
    try {
        entries_ = listFolder(folder_, extensions_);
    } catch (const std::exception& e) {
        entries_.clear();
        error_ = e.what();
    }
}

void FileDialog::setField(const std::string& text) {
    std::snprintf(field_.data(), field_.size(), "%s", text.c_str());
}

std::filesystem::path FileDialog::typedPath() const {
    const std::filesystem::path typed(field_.data());
    return typed.is_absolute() ? typed : folder_ / typed;
}

std::optional<std::filesystem::path> FileDialog::accept(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        enter(path);
        setField("");
        return std::nullopt;
    }
    open_ = false;
    return path.lexically_normal();
}

std::optional<std::filesystem::path> FileDialog::draw(ControlRects& controls) {
    if (!open_) return std::nullopt;
    const std::string id = title_ + "###file dialog";
    if (opening_) {
        ImGui::OpenPopup(id.c_str());
        opening_ = false;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(560.0f, display.x - 16.0f), std::min(440.0f, display.y - 16.0f)),
                             ImGuiCond_Appearing);
    bool keepOpen = true;
    if (!ImGui::BeginPopupModal(id.c_str(), &keepOpen)) {
        open_ = false;  // closed by its title bar's button or Escape
        return std::nullopt;
    }
    std::optional<std::filesystem::path> chosen;
    ImGui::TextWrapped("%s", folder_.c_str());
    // The list fills what the path field and the buttons below leave.
    const float below = ImGui::GetFrameHeightWithSpacing() * 2.0f + ImGui::GetStyle().ItemSpacing.y;
    ImGui::BeginChild("entries", ImVec2(0.0f, -below), true);
    // Draws one entry: a click selects it (its name in the path field), a double click enters
    // the folder or chooses the file, which ends the list for this frame. Both clicks must be on
    // this entry: a click on another one just before it is no double click.
    const auto entry = [&](const std::string& name, bool folder) {
        const bool picked = ImGui::Selectable(folder ? (name + "/").c_str() : name.c_str(),
                                              name == field_.data(), ImGuiSelectableFlags_AllowDoubleClick);
        controls.remember("dialog/" + name, false);
        if (!picked) return false;
        const bool selectedBefore = name == field_.data();
        setField(name);
        if (!ImGui::IsMouseDoubleClicked(0) || !selectedBefore) return false;
        chosen = accept(folder_ / name);
        return true;
    };
    bool changed = folder_.has_relative_path() && entry("..", true);
    // A copy: entering a folder replaces the list being drawn.
    const std::vector<FolderEntry> entries = entries_;
    for (size_t i = 0; i < entries.size() && !changed; ++i) {
        changed = entry(entries[i].name, entries[i].folder);
    }
    if (!error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", error_.c_str());
    ImGui::EndChild();

    ImGui::SetNextItemWidth(-1.0f);
    const bool entered =
        ImGui::InputText("##path", field_.data(), field_.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    controls.remember("dialog path", false);
    const bool openPressed = ImGui::Button("Open");
    controls.remember("dialog open", false);
    ImGui::SameLine();
    const bool cancelled =
        ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    controls.remember("dialog cancel", false);
    if ((entered || openPressed) && field_[0] != '\0') chosen = accept(typedPath());
    if (cancelled || !keepOpen) open_ = false;
    if (!open_) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return open_ ? std::nullopt : chosen;
}

}  // namespace strata::viewer
