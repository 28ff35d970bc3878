// The scene's folder (scene/scene_folder.h): every file a scene refers to (MTL, texture, glTF
// buffer and image, the description and its environment) resolves inside the main file's folder
// after following symlinks, and is a regular file; any other reference is refused in one line
// naming it, or read and noted with allowOutsideFiles. Each case is a model a stranger could send.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <vector>
#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"
#include "util/error.h"
#include "test_support.h"

using namespace strata;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A model's folder `model/` beside files that are not the model's: `secret.png`, `secret.mtl`
// and `outside/x.png`, as a render service's other users' files would be.
struct Folders {
    test::ScratchDir root;
    fs::path model;
    fs::path secret;
    explicit Folders(const std::string& name)
        : root(test::scratchDir(name)), model(root / "model"), secret(root / "secret.png") {
        test::writeFile(secret, "SECRET-BYTES");
        test::writeFile(root / "secret.mtl", "newmtl white\nKd 1 1 1\n");
        test::writeFile(root / "outside" / "x.png", "OUTSIDE");
        test::writeFile(model / "tex.png", "INSIDE");
    }
    // The canonical folder, as messages name it.
    std::string folder() const { return fs::canonical(model).string(); }
};

const char* const kWhiteQuadObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "usemtl white\nf 1/1 2/2 3/3 4/4\n";

// s.obj using s.mtl, whose one texture statement is `statement`.
void writeObj(const Folders& f, const std::string& statement) {
    test::writeFile(f.model / "s.obj", std::string("mtllib s.mtl\n") + kWhiteQuadObj);
    test::writeFile(f.model / "s.mtl", "newmtl white\nKd 1 1 1\n" + statement + "\n");
}

std::string refusal(const Folders& f, const std::string& where, const std::string& reference) {
    return (f.model / where).string() + " '" + reference + "' resolves outside the model's folder (" +
           f.folder() + "); --allow-outside-files reads it";
}

// A glTF triangle in s.gltf whose buffer and image have the URIs given.
void writeGltf(const Folders& f, const std::string& bufferUri, const std::string& imageUri) {
    const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    test::writeFile(f.model / "tri.bin", std::string(reinterpret_cast<const char*>(corners), sizeof corners));
    const json gltf = {
        {"asset", {{"version", "2.0"}}},
        {"buffers", {{{"byteLength", 36}, {"uri", bufferUri}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
        {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
        {"images", {{{"uri", imageUri}}}},
        {"textures", {{{"source", 0}}}},
        {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 0}}}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"scenes", {{{"nodes", {0}}}}}};
    test::writeFile(f.model / "s.gltf", gltf.dump());
}

bool hasFile(const SceneBundle& bundle, const std::string& bytes) {
    return std::any_of(bundle.files.begin(), bundle.files.end(),
                       [&](const SceneFile& file) { return file.bytes == bytes; });
}

}  // namespace

TEST_CASE("scene folder: an MTL's texture by absolute path, by ../ or through a symlink out is refused by name") {
    const Folders f("folder-mtl");
    writeObj(f, "map_Kd " + f.secret.string());
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.obj"),
                         refusal(f, "s.mtl:3: map_Kd", f.secret.string()).c_str(), Error);
    writeObj(f, "map_Kd ../secret.png");
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.obj"),
                         refusal(f, "s.mtl:3: map_Kd", "../secret.png").c_str(), Error);
    // "sub/../../secret.png" is "../secret.png" once normalised, as the bundle names it.
    writeObj(f, "map_Kd sub/../../secret.png");
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.obj"),
                         refusal(f, "s.mtl:3: map_Kd", "../secret.png").c_str(), Error);
    fs::create_symlink(f.secret, f.model / "link.png");
    writeObj(f, "map_Kd link.png");
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.obj"),
                         refusal(f, "s.mtl:3: map_Kd", "link.png").c_str(), Error);
    fs::create_directory_symlink(f.root / "outside", f.model / "linked");
    writeObj(f, "map_Kd linked/x.png");
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.obj"),
                         refusal(f, "s.mtl:3: map_Kd", "linked/x.png").c_str(), Error);
    // A symlink that stays inside is as good as the file.
    fs::create_symlink(f.model / "tex.png", f.model / "alias.png");
    writeObj(f, "map_Kd alias.png");
    CHECK(hasFile(readSceneBundle(f.model / "s.obj"), "INSIDE"));
}

TEST_CASE("scene folder: an OBJ's mtllib outside the folder is refused by name") {
    const Folders f("folder-mtllib");
    test::writeFile(f.model / "s.obj", std::string("mtllib ../secret.mtl\n") + kWhiteQuadObj);
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.obj"),
                         refusal(f, "s.obj:1: mtllib", "../secret.mtl").c_str(), Error);
}

TEST_CASE("scene folder: glTF buffer and image URIs out of the folder (absolute, ../, %2F, symlink) are refused") {
    const Folders f("folder-gltf");
    const std::string where = "s.gltf: URI";
    writeGltf(f, "tri.bin", f.secret.string());
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.gltf"), refusal(f, where, f.secret.string()).c_str(),
                         Error);
    writeGltf(f, "tri.bin", "../secret.png");
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.gltf"), refusal(f, where, "../secret.png").c_str(),
                         Error);
    // tinygltf %-decodes a URI before asking for its file; the decoded name is what is checked.
    writeGltf(f, "tri.bin", "..%2Fsecret.png");
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.gltf"), refusal(f, where, "../secret.png").c_str(),
                         Error);
    writeGltf(f, "%2E%2E/secret.png", "tex.png");
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.gltf"), refusal(f, where, "../secret.png").c_str(),
                         Error);
    fs::create_symlink(f.secret, f.model / "link.png");
    writeGltf(f, "tri.bin", "link.png");
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.gltf"), refusal(f, where, "link.png").c_str(), Error);
    // Inside, both are read.
    writeGltf(f, "tri.bin", "tex.png");
    CHECK(hasFile(readSceneBundle(f.model / "s.gltf"), "INSIDE"));
}

TEST_CASE("scene folder: the description and its environment map are confined and read only as regular files") {
    const Folders f("folder-description");
    writeObj(f, "");
    const auto describe = [&](const std::string& file) {
        test::writeFile(f.model / "s.json", R"({"environment":{"file":")" + file + R"("}})");
    };
    describe("/dev/zero");
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.obj"),
                         refusal(f, "s.json: \"environment\" file", "/dev/zero").c_str(), Error);
    // Allowed outside, /dev/zero is still no file to read (it never ends).
    CHECK_THROWS_WITH_AS(
        readSceneBundle(f.model / "s.obj", std::nullopt, {true}),
        ((f.model / "s.json").string() + ": \"environment\" file '/dev/zero' is not a regular file").c_str(),
        Error);
    // A FIFO would block the read forever: it is refused at once.
    REQUIRE(::mkfifo((f.model / "sky.exr").c_str(), 0600) == 0);
    describe("sky.exr");
    CHECK_THROWS_WITH_AS(
        readSceneBundle(f.model / "s.obj"),
        ((f.model / "s.json").string() + ": \"environment\" file 'sky.exr' is not a regular file").c_str(),
        Error);
    // The description itself is a file of the folder: a symlink out is refused.
    fs::remove(f.model / "s.json");
    fs::create_symlink(f.root / "secret.mtl", f.model / "s.json");
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.obj"),
                         refusal(f, "s.obj: scene description", "s.json").c_str(), Error);
}

TEST_CASE("scene folder: allowOutsideFiles reads the files outside and the load report says so") {
    const Folders f("folder-allowed");
    writeObj(f, "map_Kd ../secret.png");
    const SceneBundle bundle = readSceneBundle(f.model / "s.obj", std::nullopt, {true});
    CHECK(bundle.find("../secret.png"));
    const std::string note = (f.model / "s.mtl").string() +
                             ":3: map_Kd '../secret.png' is outside the model's folder (" + f.folder() +
                             "); read as --allow-outside-files allows";
    CHECK(bundle.outsideNotes == std::vector<std::string>{note});
    // The note reaches the report's warnings, which the programs print and the viewer shows.
    const LoadedScene loaded = parseScene(bundle);
    CHECK(std::find(loaded.report.warnings.begin(), loaded.report.warnings.end(), note) !=
          loaded.report.warnings.end());
}

TEST_CASE("scene folder: a missing texture inside stays a warning, and the scene file must be a regular file") {
    const Folders f("folder-missing");
    writeObj(f, "map_Kd gone.png");
    const LoadedScene loaded = loadScene(f.model / "s.obj");
    CHECK(loaded.report.warnings ==
          std::vector<std::string>{(f.model / "s.mtl").string() +
                                   ":3: map_Kd: texture file 'gone.png' is missing; using the factor alone"});
    REQUIRE(::mkfifo((f.model / "pipe.obj").c_str(), 0600) == 0);
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "pipe.obj"),
                         ((f.model / "pipe.obj").string() + ": no such scene file").c_str(), Error);
}

TEST_CASE("scene folder: a buffer of another file's bytes never shows them: an index error names its position") {
    const Folders f("folder-buffer-bytes");
    const std::string passwd = "root:x:0:0:root:/root:/bin/bash\n";
    test::writeFile(f.root / "passwd", passwd);
    const auto gltf = [&](const std::string& uri, size_t length) {
        // Positions from a data: buffer, indices (UNSIGNED_INT) over the other file's bytes.
        const json model = {
            {"asset", {{"version", "2.0"}}},
            {"buffers",
             {{{"byteLength", 36},
               {"uri", "data:application/octet-stream;base64,"
                       "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}},
              {{"byteLength", length}, {"uri", uri}}}},
            {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}, {{"buffer", 1}, {"byteLength", length}}}},
            {"accessors",
             {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
              {{"bufferView", 1}, {"componentType", 5125}, {"count", length / 4}, {"type", "SCALAR"}}}},
            {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
            {"nodes", {{{"mesh", 0}}}},
            {"scenes", {{{"nodes", {0}}}}}};
        test::writeFile(f.model / "s.gltf", model.dump());
    };
    gltf((f.root / "passwd").string(), passwd.size());
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.gltf"),
                         refusal(f, "s.gltf: URI", (f.root / "passwd").string()).c_str(), Error);
    gltf("/proc/self/environ", 4096);
    CHECK_THROWS_WITH_AS(readSceneBundle(f.model / "s.gltf"),
                         refusal(f, "s.gltf: URI", "/proc/self/environ").c_str(), Error);
    // Allowed, the file is read; its bytes as indices are out of range, and the message says where, not what.
    gltf((f.root / "passwd").string(), passwd.size());
    std::string message;
    try {
        parseScene(readSceneBundle(f.model / "s.gltf", std::nullopt, {true}));
    } catch (const Error& error) {
        message = error.what();
    }
    CHECK(message ==
          (f.model / "s.gltf").string() + ": every triangle uses an index past its primitive's vertices; nothing is left");
    for (size_t i = 0; i + 4 <= passwd.size(); i += 4) {
        uint32_t word;
        std::memcpy(&word, passwd.data() + i, sizeof word);
        CHECK(message.find(std::to_string(word)) == std::string::npos);
    }
}
