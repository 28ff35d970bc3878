// EXT_meshopt_compression (gltf_meshopt.h): bufferViews encoded here with libmeshoptimizer's
// encoders (vertex attributes, triangle indices, index sequences, the octahedral, quaternion and
// exponential filters), their fallback buffers without data, in .gltf and .glb files, decode to
// the geometry they were made of; malformed ones are one line naming the bufferView.
#include <doctest/doctest.h>

#include <cstdint>
#include <string>
#include <vector>
#include <glm/geometric.hpp>
#include <meshoptimizer.h>

#include "scene/gltf_loader.h"
#include "scene/gltf_test_model.h"
#include "util/error.h"

using namespace strata;
using nlohmann::json;
using test::errorOf;

namespace {

// A unit quad in z = 0, its four corners.
const std::vector<float> kCorners{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

// A model whose bufferViews hold meshopt-encoded bytes in buffer 0 and name buffer 1, a fallback
// without data, as their own.
struct MeshoptModel : test::Model {
    MeshoptModel() {
        doc["extensionsUsed"] = {"EXT_meshopt_compression"};
        doc["extensionsRequired"] = {"EXT_meshopt_compression"};
        doc["buffers"] = json::array({{{"byteLength", 4096}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}});
    }

    // A compressed view of `count` elements of `stride` bytes; returns its index.
    int view(const std::string& encoded, size_t count, size_t stride, const char* mode, const char* filter = "NONE") {
        json extension = {{"buffer", 0},       {"byteOffset", bin.size()}, {"byteLength", encoded.size()},
                          {"byteStride", stride}, {"count", count},          {"mode", mode}};
        if (std::string(filter) != "NONE") extension["filter"] = filter;
        json view = {{"buffer", 1}, {"byteLength", count * stride}, {"extensions", {{"EXT_meshopt_compression", extension}}}};
        if (std::string(mode) == "ATTRIBUTES") view["byteStride"] = stride;
        doc["bufferViews"].push_back(view);
        bin += encoded;
        while (bin.size() % 4) bin += '\0';
        return static_cast<int>(doc["bufferViews"].size() - 1);
    }
    int accessorOf(int view, int componentType, size_t count, const char* type, bool normalized = false) {
        doc["accessors"].push_back({{"bufferView", view}, {"componentType", componentType}, {"count", count},
                                    {"type", type}, {"normalized", normalized}});
        return static_cast<int>(doc["accessors"].size() - 1);
    }
};

template <typename T>
std::string encodeVertices(const std::vector<T>& elements, size_t count) {
    const size_t stride = elements.size() * sizeof(T) / count;
    std::string out(meshopt_encodeVertexBufferBound(count, stride), '\0');
    out.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(out.data()), out.size(), elements.data(),
                                          count, stride));
    return out;
}

std::string encodeTriangles(const std::vector<uint32_t>& indices, size_t vertices) {
    std::string out(meshopt_encodeIndexBufferBound(indices.size(), vertices), '\0');
    out.resize(meshopt_encodeIndexBuffer(reinterpret_cast<unsigned char*>(out.data()), out.size(), indices.data(),
                                         indices.size()));
    return out;
}

std::string encodeSequence(const std::vector<uint32_t>& indices, size_t vertices) {
    std::string out(meshopt_encodeIndexSequenceBound(indices.size(), vertices), '\0');
    out.resize(meshopt_encodeIndexSequence(reinterpret_cast<unsigned char*>(out.data()), out.size(), indices.data(),
                                           indices.size()));
    return out;
}

// The quad twice: positions through the exponential filter and triangle indices (16-bit), then
// octahedral normals and an index sequence (32-bit); quaternion-filtered "normals" on a third.
MeshoptModel quadModel() {
    MeshoptModel model;
    std::vector<uint32_t> exponential(12);
    meshopt_encodeFilterExp(exponential.data(), 4, 12, 24, kCorners.data());
    const int positions = model.accessorOf(model.view(encodeVertices(exponential, 4), 4, 12, "ATTRIBUTES", "EXPONENTIAL"),
                                           5126, 4, "VEC3");
    const std::vector<uint32_t> corners{0, 1, 2, 0, 2, 3};
    const int triangles = model.accessorOf(model.view(encodeTriangles(corners, 4), 6, 2, "TRIANGLES"), 5123, 6, "SCALAR");
    model.meshNode({{"attributes", {{"POSITION", positions}}}, {"indices", triangles}});

    const std::vector<float> up{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};  // x, y, z, w per normal
    std::vector<int8_t> octahedral(16);
    meshopt_encodeFilterOct(octahedral.data(), 4, 4, 8, up.data());
    const int normals = model.accessorOf(model.view(encodeVertices(octahedral, 4), 4, 4, "ATTRIBUTES", "OCTAHEDRAL"),
                                         5120, 4, "VEC3", true);
    const int sequence = model.accessorOf(model.view(encodeSequence(corners, 4), 6, 4, "INDICES"), 5125, 6, "SCALAR");
    model.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}, {"indices", sequence}},
                   {{"translation", {0, 0, 1}}});

    // A unit quaternion (0.6, 0, 0.8, 0) per vertex: its x, y, z read as a normal are (0.6, 0, 0.8).
    const std::vector<float> rotation{0.6f, 0, 0.8f, 0, 0.6f, 0, 0.8f, 0, 0.6f, 0, 0.8f, 0, 0.6f, 0, 0.8f, 0};
    std::vector<int16_t> quaternion(16);
    meshopt_encodeFilterQuat(quaternion.data(), 4, 8, 12, rotation.data());
    const int turned = model.accessorOf(model.view(encodeVertices(quaternion, 4), 4, 8, "ATTRIBUTES", "QUATERNION"),
                                        5122, 4, "VEC3", true);
    model.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", turned}}}, {"indices", triangles}},
                   {{"translation", {0, 0, 2}}});
    return model;
}


}  // namespace

TEST_CASE("gltf meshopt: encoded attributes, indices and filters decode to the quads they were made of") {
    const MeshoptModel model = quadModel();
    for (const bool binary : {false, true}) {
        CAPTURE(binary);
        const MeshData mesh =
            parseGltfScene(binary ? test::bundleOf(model.glb(), "model.glb") : test::bundleOf(model.gltf())).mesh;
        REQUIRE(mesh.triangles.size() == 6);
        REQUIRE(mesh.positions.size() == 12);
        for (size_t v = 0; v < 12; ++v) {
            const size_t corner = v % 4;
            CHECK(mesh.positions[v] == glm::vec3(kCorners[3 * corner], kCorners[3 * corner + 1], float(v / 4)));
        }
        CHECK(mesh.triangles[1] == std::array<uint32_t, 3>{0, 2, 3});
        CHECK(mesh.triangles[3] == std::array<uint32_t, 3>{4, 6, 7});
        REQUIRE(mesh.normals.size() == 8);
        for (size_t n = 0; n < 4; ++n) CHECK(mesh.normals[n] == glm::vec3(0, 0, 1));
        for (size_t n = 4; n < 8; ++n) {
            CHECK(mesh.normals[n].x == doctest::Approx(0.6f).epsilon(1e-3));
            CHECK(mesh.normals[n].y == doctest::Approx(0.0f));
            CHECK(mesh.normals[n].z == doctest::Approx(0.8f).epsilon(1e-3));
        }
    }
}

TEST_CASE("gltf meshopt: KHR_meshopt_compression is read as EXT_meshopt_compression") {
    MeshoptModel model = quadModel();
    std::string renamed = model.doc.dump();
    for (size_t at; (at = renamed.find("EXT_meshopt_compression")) != std::string::npos;) {
        renamed.replace(at, 3, "KHR");
    }
    model.doc = json::parse(renamed);
    CHECK(parseGltfScene(test::bundleOf(model.gltf())).mesh.triangles.size() == 6);
}

TEST_CASE("gltf meshopt: malformed compressed views are one line naming the bufferView") {
    const std::string where = "mem/model.gltf: bufferView 0: EXT_meshopt_compression: ";
    MeshoptModel garbled = quadModel();
    std::fill(garbled.bin.begin(), garbled.bin.begin() + 8, '\xff');
    CHECK(errorOf(garbled) == where + "the data does not decode (meshoptimizer error -1)");
    MeshoptModel past = quadModel();
    past.doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteLength"] = 1 << 20;
    CHECK(errorOf(past) == where + "its byteOffset and byteLength run past the end of buffer 0");
    MeshoptModel stride = quadModel();
    stride.doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteStride"] = 6;
    CHECK(errorOf(stride) == where + "byteStride 6 is not allowed for mode ATTRIBUTES");
    MeshoptModel filter = quadModel();
    filter.doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["filter"] = "SPIRAL";
    CHECK(errorOf(filter) == where + "unknown filter 'SPIRAL' (known: NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL)");
    MeshoptModel huge = quadModel();
    huge.doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["count"] = 4294967295.0;
    CHECK(errorOf(huge) == where + "byteStride 12 x count 4294967295 is not a buffer size");
}
