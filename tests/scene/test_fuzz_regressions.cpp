// Replays the loader fuzzer's seed corpus and every finding it has made (tests/fuzz/findings/,
// one file per finding, named by libFuzzer) through the same code the fuzzer runs, in every build:
// a finding, once fixed, stays fixed. scripts/check.sh fuzz explains how findings arrive here.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "fuzz/loader_input.h"
#include "scene/obj_loader.h"
#include "scene/scene_description.h"
#include "scene/scene_format.h"
#include "util/error.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("fuzz regressions: every seed and every finding is accepted or refused cleanly") {
    size_t findings = 0;
    for (const char* folder : {"tests/fuzz/corpus", "tests/fuzz/findings"}) {
        for (const auto& entry : std::filesystem::directory_iterator(test::sourceDir() / folder)) {
            const std::string name = entry.path().filename().string();
            CAPTURE(name);
            CHECK_NOTHROW(fuzz::parseLoaderInput(test::fileBytes(entry.path())));
            findings += std::string(folder).find("findings") != std::string::npos;
        }
    }
    CHECK(findings >= 1);
}

TEST_CASE("fuzz regressions: a '#' inside a face line hides the rest of it from the loader too") {
    // Finding crash-f406ca82: the line checks read "f 1 2 3/1#/1 5" as "f 1 2 3/1", tinyobjloader
    // read the 5 as well and the loader indexed past the 4th and last vertex.
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nf 1 2 3/1#/1 5\nf 1 3 4 # 5\n";
    LoadReport report;
    const MeshData mesh = parseObj(obj, "hash.obj", "", "hash.mtl", &report);
    CHECK(mesh.triangles.size() == 2);
    CHECK(report.faces == 2);
}

TEST_CASE("fuzz regressions: nan, inf and out-of-range numbers in OBJ and MTL text") {
    LoadReport report;
    const MeshData mesh = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv 0 -inf 0\nf 1 2 3\nf 1 2 4\nf 1 5 3\n",
                                   "n.obj", "", "n.mtl", &report);
    // tinyobjloader alone reads "nan" as 0, which made the 2nd face a valid triangle.
    CHECK(mesh.triangles.size() == 1);
    CHECK(report.droppedTriangles == 2);
    CHECK(report.nonFiniteVertices == 2);
    CHECK_THROWS_WITH_AS(parseObj("v 0 0 1e39\n", "big.obj", "", "m", nullptr),
                         "big.obj:1: '1e39' is out of range for a 32-bit float", Error);
    CHECK_THROWS_WITH_AS(parseObj("", "o.obj", "newmtl a\nKd nan 0 0\n", "nan.mtl", nullptr),
                         "nan.mtl:2: 'nan' is not a finite number", Error);
}

TEST_CASE("fuzz regressions: a JSON number beyond double range is a scene-description error") {
    // Finding crash-4633922f: nlohmann threw out_of_range, not parse_error, and it escaped.
    CHECK_THROWS_WITH_AS(parseSceneDescription("{\"fov_y\": 1e395}", "big.json"),
                         "big.json: invalid JSON: number overflow parsing '1e395'", Error);
}

TEST_CASE("fuzz regressions: a binary glTF whose BIN chunk claims its header's 8 bytes as data is refused") {
    // Finding crash-glb-bin-chunk-over-read (376 bytes): tinygltf 2.7 copied the buffer from 8 bytes
    // past the end of the file (AddressSanitizer: heap-buffer-overflow); a Release build rendered it.
    const std::string finding = test::fileBytes(test::sourceDir() / "tests/fuzz/findings/crash-glb-bin-chunk-over-read");
    std::string_view input = finding;  // the glTF part, the 4th
    for (int part = 0; part < 3; ++part) input.remove_prefix(input.find(fuzz::kPartSeparator) + fuzz::kPartSeparator.size());
    const std::string glb(input.substr(0, input.find(fuzz::kPartSeparator)));
    REQUIRE(glb.size() == 376);
    const SceneBundle bundle{"mem/over-read.glb", {{"over-read.glb", glb}}, std::nullopt, std::nullopt};
    CHECK_THROWS_WITH_AS(parseSceneFile(bundle), "mem/over-read.glb: binary glTF chunk 1 claims 296 bytes, 288 are left",
                         Error);
    // The header's own length, and a chunk header cut short, are checked too.
    std::string longer = glb;
    longer[8] = static_cast<char>(static_cast<unsigned char>(longer[8]) + 4);
    CHECK_THROWS_WITH_AS(parseSceneFile({"mem/x.glb", {{"x.glb", longer}}, std::nullopt, std::nullopt}),
                         "mem/x.glb: the binary glTF header gives a length of 380 bytes, the file has 376", Error);
    CHECK_THROWS_WITH_AS(parseSceneFile({"mem/x.glb", {{"x.glb", glb.substr(0, 16)}}, std::nullopt, std::nullopt}),
                         "mem/x.glb: the binary glTF header gives a length of 376 bytes, the file has 16", Error);
}

TEST_CASE("fuzz regressions: an image whose buffer view runs past its buffer is refused") {
    // Finding crash-gltf-image-view-past-buffer: a glTF 1.0 .glb (upgraded, gltf_version1.h) whose
    // image view ends a byte past its 145-byte body. tinygltf 2.7 passed the view to the image
    // callback unchecked (AddressSanitizer: heap-buffer-overflow in keepEncodedImage's copy); a
    // glTF 2.0 file with such a view did the same.
    const std::string finding =
        test::fileBytes(test::sourceDir() / "tests/fuzz/findings/crash-gltf-image-view-past-buffer");
    std::string_view input = finding;  // the glTF part, the 4th
    for (int part = 0; part < 3; ++part) input.remove_prefix(input.find(fuzz::kPartSeparator) + fuzz::kPartSeparator.size());
    const std::string glb(input.substr(0, input.find(fuzz::kPartSeparator)));
    const SceneBundle bundle{"mem/view.glb", {{"view.glb", glb}}, std::nullopt, std::nullopt};
    CHECK_THROWS_WITH_AS(parseSceneFile(bundle),
                         "mem/view.glb: image 0: bufferView 0 (byteOffset 68, byteLength 78) runs past the end of "
                         "buffer 0 (145 bytes)",
                         Error);
}
