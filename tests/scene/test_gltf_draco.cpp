// KHR_draco_mesh_compression (gltf_draco.h): primitives encoded here with libdraco's encoder
// decode to the geometry they were made of; malformed Draco data is one line naming the
// primitive; and, when assimp's test models are installed, the Draco-compressed 2CylinderEngine
// loads and renders as its uncompressed twin does.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <vector>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <glm/geometric.hpp>

#include "render_support.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_test_model.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/error.h"

using namespace strata;
using nlohmann::json;
using test::errorOf;

namespace {

// A unit quad in z = 0 facing +z, as two triangles with their normals.
const std::vector<std::array<glm::vec3, 3>> kQuad{{glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 1, 0)},
                                                  {glm::vec3(0, 0, 0), glm::vec3(1, 1, 0), glm::vec3(0, 1, 0)}};

struct Encoded {
    std::string bytes;
    int positionId;
    int normalId;
};

// The triangles encoded by libdraco, positions unquantized (so that they decode exactly).
Encoded dracoQuad() {
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(static_cast<int>(kQuad.size()));
    const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int normal = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
    const glm::vec3 up(0, 0, 1);
    for (size_t f = 0; f < kQuad.size(); ++f) {
        const draco::FaceIndex face(static_cast<uint32_t>(f));
        builder.SetAttributeValuesForFace(position, face, &kQuad[f][0], &kQuad[f][1], &kQuad[f][2]);
        builder.SetAttributeValuesForFace(normal, face, &up, &up, &up);
    }
    const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    REQUIRE(mesh);
    draco::Encoder encoder;
    draco::EncoderBuffer buffer;
    REQUIRE(encoder.EncodeMeshToBuffer(*mesh, &buffer).ok());
    return {std::string(buffer.data(), buffer.size()), static_cast<int>(mesh->attribute(position)->unique_id()),
            static_cast<int>(mesh->attribute(normal)->unique_id())};
}

// A model whose one primitive is `encoded`: its accessors have counts and types but no data.
test::Model dracoModel(const Encoded& encoded) {
    test::Model model;
    model.doc["bufferViews"].push_back({{"buffer", 0}, {"byteLength", encoded.bytes.size()}});
    model.bin += encoded.bytes;
    while (model.bin.size() % 4) model.bin += '\0';
    model.doc["accessors"] = json::array({{{"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
                                          {{"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                                          {{"componentType", 5126}, {"count", 4}, {"type", "VEC3"}}});
    model.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    model.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    model.meshNode({{"attributes", {{"POSITION", 1}, {"NORMAL", 2}}},
                    {"indices", 0},
                    {"extensions",
                     {{"KHR_draco_mesh_compression",
                       {{"bufferView", 0}, {"attributes", {{"POSITION", encoded.positionId}, {"NORMAL", encoded.normalId}}}}}}}});
    return model;
}


// A triangle's corners in a canonical order (the decoder may renumber the points and start a
// triangle at another corner, but keeps its winding).
std::array<glm::vec3, 3> canonical(std::array<glm::vec3, 3> t) {
    const auto less = [](const glm::vec3& a, const glm::vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    while (!(less(t[0], t[1]) && less(t[0], t[2]))) std::rotate(t.begin(), t.begin() + 1, t.end());
    return t;
}

}  // namespace

TEST_CASE("gltf draco: a Draco-encoded primitive decodes to its triangles, windings and normals") {
    const MeshData mesh = parseGltfScene(test::bundleOf(dracoModel(dracoQuad()).gltf())).mesh;
    REQUIRE(mesh.triangles.size() == kQuad.size());
    std::vector<std::array<glm::vec3, 3>> decoded;
    for (const auto& t : mesh.triangles) {
        decoded.push_back(canonical({mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]}));
    }
    std::vector<std::array<glm::vec3, 3>> expected;
    for (const auto& t : kQuad) expected.push_back(canonical(t));
    for (const auto& t : expected) CHECK(std::count(decoded.begin(), decoded.end(), t) == 1);
    REQUIRE(mesh.normals.size() == mesh.positions.size());
    for (const glm::vec3& n : mesh.normals) CHECK(n == glm::vec3(0, 0, 1));
    CHECK(mesh.triangleNormals[0] != kNoNormals);
}

TEST_CASE("gltf draco: malformed Draco data or references are one line naming the primitive") {
    const Encoded encoded = dracoQuad();
    const std::string where = "mem/model.gltf: mesh 'm0' (0) primitive 0: KHR_draco_mesh_compression: ";
    Encoded garbled = encoded;
    std::fill(garbled.bytes.begin(), garbled.bytes.end(), '\x5a');
    const std::string undecodable = errorOf(dracoModel(garbled));
    CHECK(undecodable.rfind(where + "the data does not decode (", 0) == 0);
    CHECK(undecodable.find('\n') == std::string::npos);
    Encoded wrongId = encoded;
    wrongId.normalId = 9;
    CHECK(errorOf(dracoModel(wrongId)) == where + "attribute NORMAL: the Draco data has no attribute 9");
    test::Model pastBuffer = dracoModel(encoded);
    pastBuffer.doc["bufferViews"][0]["byteLength"] = 1 << 20;
    CHECK(errorOf(pastBuffer) == where + "bufferView 0 runs past the end of its buffer");
    test::Model wrongType = dracoModel(encoded);
    wrongType.doc["accessors"][2]["type"] = "VEC2";
    CHECK(errorOf(wrongType) ==
          where + "attribute NORMAL: the Draco data's 3 components do not convert to its accessor's type");
}

TEST_CASE("gltf draco: assimp's Draco 2CylinderEngine opens and renders as the uncompressed one") {
    const std::filesystem::path root = "/usr/share/assimp/models/glTF2";
    if (!std::filesystem::is_directory(root / "draco")) {
        MESSAGE("assimp-testmodels not installed: " << root / "draco" << " is absent, skipped");
        return;
    }
    const LoadedScene draco = loadScene(root / "draco/2CylinderEngine.gltf");
    const LoadedScene plain = loadScene(root / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    // The same triangles placed: Draco's encoder left out the 11160 degenerate ones that the
    // uncompressed file holds and loading drops, and its quantization made 14 (of 110336)
    // degenerate, which loading drops in turn.
    CHECK(plain.report.droppedTriangles == 11160);
    CHECK(draco.scene.summary().placedTriangles + draco.report.droppedTriangles == plain.scene.summary().placedTriangles);
    CHECK(draco.report.droppedTriangles < plain.scene.summary().placedTriangles / 1000);
    // Draco quantizes positions (here to 1/2^14 of each primitive's extent at worst): the boxes
    // agree to a thousandth of the model's size.
    const float size = glm::length(plain.scene.boundsMax() - plain.scene.boundsMin());
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(std::abs(draco.scene.boundsMin()[axis] - plain.scene.boundsMin()[axis]) < 1e-3f * size);
        CHECK(std::abs(draco.scene.boundsMax()[axis] - plain.scene.boundsMax()[axis]) < 1e-3f * size);
    }
    // Rendered from the same (framing) camera, pixel by pixel: the mean difference is within
    // 4 standard errors of the pixels' differences (quantization moves a few edge pixels).
    const Camera camera(plain.settings.pose, 48, 32);
    RenderSettings settings;
    settings.seed = 7;
    const std::vector<double> a = test::pixelLuminances(test::renderPasses(draco.scene, camera, settings, 4));
    const std::vector<double> b = test::pixelLuminances(test::renderPasses(plain.scene, camera, settings, 4));
    std::vector<double> difference(a.size());
    for (size_t i = 0; i < a.size(); ++i) difference[i] = a[i] - b[i];
    const test::MeanEstimate meanB = test::estimateMean(b);
    const test::MeanEstimate gap = test::estimateMean(difference);
    CAPTURE(meanB.mean);
    CAPTURE(gap.mean);
    CAPTURE(gap.standardError);
    CHECK(meanB.mean > 0.05);
    CHECK(std::abs(gap.mean) < 4.0 * gap.standardError + 1e-3 * meanB.mean);
}
