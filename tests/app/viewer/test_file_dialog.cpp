// The viewer's file dialog without drawing it: what it lists of a folder and where it opens.
// Clicking through it is in test_viewer_panel.cpp.
#include <doctest/doctest.h>

#include <fstream>

#include "file_dialog.h"
#include "test_support.h"
#include "util/error.h"

using namespace strata;
using namespace strata::viewer;

namespace {

const std::vector<std::string> kScenes{".obj", ".gltf", ".glb"};

}  // namespace

TEST_CASE("file dialog: a folder lists its subfolders, then its files of the wanted extensions in any case") {
    const auto dir = test::scratchDir("file-dialog-list");
    for (const char* folder : {"rooms", "Assets", ".git"}) std::filesystem::create_directory(dir / folder);
    for (const char* file : {"b.gltf", "A.OBJ", "notes.txt", ".hidden.obj", "sky.exr", "c.glb", "obj"}) {
        std::ofstream(dir / file) << "x";
    }
    std::filesystem::create_symlink(dir / "gone.obj", dir / "dangling.obj");
    const std::vector<FolderEntry> expected{
        {"Assets", true}, {"rooms", true}, {"A.OBJ", false}, {"b.gltf", false}, {"c.glb", false}};
    CHECK(listFolder(dir, kScenes) == expected);
    CHECK(listFolder(dir, {".exr"}) ==
          std::vector<FolderEntry>{{"Assets", true}, {"rooms", true}, {"sky.exr", false}});
    try {
        listFolder(dir / "missing", kScenes);
        FAIL("listed a folder that is not there");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).rfind((dir / "missing").string() + ": cannot list the folder (", 0) == 0);
    }
}

TEST_CASE("file dialog: it opens in the folder of the path given, or the nearest one above it") {
    const auto dir = test::scratchDir("file-dialog-open");
    std::filesystem::create_directories(dir / "scenes/box");
    std::ofstream(dir / "scenes/box/box.obj") << "x";
    FileDialog dialog;
    dialog.open("Open a scene", dir / "scenes/box/box.obj", kScenes);
    CHECK(dialog.isOpen());
    CHECK(dialog.folder() == dir / "scenes/box");
    CHECK(dialog.entries() == std::vector<FolderEntry>{{"box.obj", false}});
    dialog.open("Open a scene", dir / "scenes/gone/also-gone.obj", kScenes);
    CHECK(dialog.folder() == dir / "scenes");
    dialog.open("Open a scene", dir / "scenes/", kScenes);
    CHECK(dialog.folder() == dir / "scenes");
    dialog.enter(dir / "scenes/box/..");
    CHECK(dialog.folder() == dir / "scenes");
    CHECK(dialog.entries() == std::vector<FolderEntry>{{"box", true}});
}
