#pragma once
// The folder of a scene's main file, through which the reading step (scene_format.h) reads every
// file the scene refers to: an OBJ's MTL files and textures, a glTF's buffers and images, the
// scene description and its environment map. A model may come from anyone (a download, an upload
// to a render service), so each reference must resolve inside this folder after following
// symlinks, and to a regular file: "../../x.png", "/etc/passwd", a symlink out of the folder or
// a FIFO would otherwise put another file's contents into the render or an error message, or hang
// the read. A reference that resolves outside is refused, and the scene with it, as a render
// service needs by default (a model that needs such a file does not render as its author meant
// without it either); SceneReadOptions::allowOutsideFiles opens the rest of the file system for a
// user's own scenes, noting each file read from outside.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace strata {

struct SceneReadOptions {
    // Read references that resolve outside the main file's folder (--allow-outside-files).
    bool allowOutsideFiles = false;
};

class SceneFolder {
public:
    // The folder of `mainFile` (which need not exist yet), canonicalised.
    SceneFolder(const std::filesystem::path& mainFile, const SceneReadOptions& options);

    // The bytes of the file `reference` names (relative to the folder, or absolute); nullopt when
    // there is nothing at that path. `where` starts every message about it ("cube.mtl:7: map_Kd");
    // throws strata::Error "WHERE 'REFERENCE' resolves outside the model's folder (FOLDER);
    // --allow-outside-files reads it" unless allowed, "... is not a regular file" or
    // "... cannot be read".
    std::optional<std::string> read(const std::string& reference, const std::string& where);

    // The same for a file that must be there: "WHERE 'REFERENCE': no such file" when it is not.
    std::string require(const std::string& reference, const std::string& where);

    // One line for each file read from outside the folder, as allowed: "WHERE 'REFERENCE' is
    // outside the model's folder (FOLDER); read as --allow-outside-files allows".
    const std::vector<std::string>& outsideNotes() const { return outsideNotes_; }

private:
    std::filesystem::path folder_;  // canonical
    SceneReadOptions options_;
    std::vector<std::string> outsideNotes_;
};

}  // namespace strata
