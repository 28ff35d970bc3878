// Bad input, table-driven: every loader and option answers with one line "strata: ..." naming the
// file and line or the option, a non-zero exit, no crash or hang, and an existing output file left
// untouched. The same tables are docs/reliability.md's "Bad input" and "Tolerated input".
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "util/error.h"
#include "image_support.h"
#include "io/image_io.h"
#include "test_support.h"

using namespace strata;

namespace {

// A valid scene to mutate: a unit quad light above a floor, with its material library and its
// description (the camera).
const std::string kObj =
    "mtllib s.mtl\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nusemtl white\nf 1 3 2\nf 1 4 3\n";
const std::string kMtl = "newmtl white\nKd 0.5 0.5 0.5\nKe 1 1 1\n";
const std::string kCamera =
    R"({"position":[0.5,1,-1],"look_at":[0.5,0,0.5],"up":[0,1,0],"fov_y":60,"width":4,"height":4})";

// A glTF triangle to mutate: positions (accessor 0) and indices 0 1 7 (accessor 1, 7 out of
// range) in a buffer (base64 data: by default); `primitive` and `extra` are spliced into its
// primitive and its top level.
std::string gltfTriangle(const std::string& primitive, const std::string& extra = "",
                         const std::string& buffer = "\"data:application/octet-stream;base64,"
                                                     "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAcAAAA=\"") {
    return R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":44,"uri":)" + buffer +
           R"(}],"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
           R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0})" + primitive + R"(}]}],)"
           R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])" + extra + "}";
}

// The exit statuses (app/usage.h): a file is missing, unreadable, malformed or cannot be written;
// the command line itself is wrong.
constexpr int kBadInput = 1;
constexpr int kBadUsage = 2;

// The triangle (without its indices) on the node list `nodes`, whose first node is the scene's.
std::string gltfTriangleOnNodes(const std::string& nodes) {
    std::string gltf = gltfTriangle("");
    const std::string oneNode = R"("nodes":[{"mesh":0}])";
    return gltf.replace(gltf.find(oneNode), oneNode.size(), "\"nodes\":" + nodes);
}

// The triangle used by three nodes: one primitive stored, placed three times.
std::string gltfPlacedThrice() {
    return gltfTriangleOnNodes(R"([{"children":[1,2,3]},{"mesh":0},{"mesh":0},{"mesh":0}])");
}

// An 8 x 4 environment map's EXR file: 384 bytes of texels.
std::string skyExr() {
    const auto dir = test::scratchDir("bad-input-sky");
    writeImage(dir / "sky.exr", Image{8, 4, std::vector<glm::vec3>(32, glm::vec3(0.5f))});
    return test::fileBytes(dir / "sky.exr");
}
struct BadInputCase {
    const char* what;       // the case, as docs/reliability.md describes it
    std::map<std::string, std::string> files;  // written into the case's folder (s.obj etc.)
    const char* arguments;  // strata's arguments; {dir} is the case's folder
    const char* expected;   // text the one error line must contain
    int exitStatus = kBadInput;
};

// Files a case does not name are the valid ones above.
const std::vector<BadInputCase> kCliCases = {
    // Scene file
    {"scene file of an unknown format", {{"s.fbx", kObj}}, "render {dir}/s.fbx",
     "s.fbx: unknown scene format '.fbx' (known: .obj, .gltf, .glb)"},
    {"scene file of an unknown format, missing", {}, "render {dir}/absent.fbx",
     "absent.fbx: no such scene file"},
    // OBJ
    {"OBJ file missing", {}, "render {dir}/absent.obj", "absent.obj: no such scene file"},
    {"OBJ path is a directory", {}, "render {dir}", "is a folder, not a scene file (give one of its .obj, .gltf, .glb files)"},
    {"OBJ malformed number", {{"s.obj", "mtllib s.mtl\nv 0 0 0\nv 1 x 0\n"}}, "render {dir}/s.obj",
     "s.obj:3: 'x' is not a number"},
    {"OBJ vertex with 2 coordinates", {{"s.obj", "v 0 0\n"}}, "render {dir}/s.obj",
     "s.obj:1: 'v' takes 3 to 7 numbers, got 2"},
    {"OBJ coordinate beyond float range", {{"s.obj", "v 0 0 1e39\n"}}, "render {dir}/s.obj",
     "s.obj:1: '1e39' is out of range"},
    {"OBJ coordinate beyond double range", {{"s.obj", "v 0 0 1e400\n"}}, "render {dir}/s.obj",
     "s.obj:1: '1e400' is out of range"},
    {"OBJ malformed normal", {{"s.obj", "vn 0 x 1\n"}}, "render {dir}/s.obj", "s.obj:1: 'x' is not a number"},
    {"OBJ normal index out of range", {{"s.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n"}},
     "render {dir}/s.obj", "s.obj:5: normal index 2 is out of range"},
    {"OBJ face index out of range", {{"s.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"}},
     "render {dir}/s.obj", "s.obj:4: vertex index 4 is out of range"},
    {"OBJ relative face index before the first vertex", {{"s.obj", "v 0 0 0\nf -1 -2 -3\n"}},
     "render {dir}/s.obj", "s.obj:2: vertex index -2 is out of range"},
    {"OBJ face index 0", {{"s.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"}}, "render {dir}/s.obj",
     "s.obj:4: '0' is not a face vertex"},
    {"OBJ face of 2 vertices", {{"s.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"}}, "render {dir}/s.obj",
     "s.obj:3: a face needs at least 3 vertices"},
    {"OBJ face index overflowing", {{"s.obj", "v 0 0 0\nf 1 1 99999999999999999999\n"}},
     "render {dir}/s.obj", "s.obj:2: '99999999999999999999' is not a face vertex"},
    {"OBJ empty", {{"s.obj", ""}}, "render {dir}/s.obj", "s.obj: the scene has no usable triangles"},
    {"OBJ only degenerate and NaN triangles",
     {{"s.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv nan 0 0\nf 1 2 3\nf 1 2 4\n"}}, "render {dir}/s.obj",
     "s.obj: the scene has no usable triangles"},
    {"OBJ binary garbage", {{"s.obj", std::string("\x7f" "ELF\x02\x01\x01\0\0\0v\xff\xfe f \x80", 17)}},
     "render {dir}/s.obj", "s.obj: the scene has no usable triangles"},
    {"OBJ in UTF-16 of an odd length", {{"s.obj", std::string("\xff\xfev\0 ", 5)}}, "render {dir}/s.obj",
     "s.obj: UTF-16 text of an odd number of bytes"},
    // glTF
    {"glTF malformed JSON", {{"s.gltf", R"({"asset": {"version": "2.0"},)"}}, "render {dir}/s.gltf",
     "s.gltf: [json.exception.parse_error.101] parse error at line 1"},
    {"glTF unknown required extension",
     {{"s.gltf", gltfTriangle("", R"(,"extensionsRequired":["KHR_materials_iridescence"])")}},
     "render {dir}/s.gltf", "s.gltf: requires extension KHR_materials_iridescence, which Strata does not implement"},
    {"glTF primitive of lines", {{"s.gltf", gltfTriangle(R"(,"mode":1)")}}, "render {dir}/s.gltf",
     "s.gltf: the file holds only lines, no surfaces"},
    {"glTF every triangle with an index out of range", {{"s.gltf", gltfTriangle(R"(,"indices":1)")}},
     "render {dir}/s.gltf", "s.gltf: every triangle uses an index past its primitive's vertices; nothing is left"},
    {"glTF buffer file missing", {{"s.gltf", gltfTriangle("", "", R"("gone.bin")")}}, "render {dir}/s.gltf",
     "s.gltf: File not found : gone.bin"},
    {"glTF emissiveStrength beyond float range",
     {{"s.gltf", gltfTriangle(R"(,"material":0)", R"(,"materials":[{"emissiveFactor":[1,1,1],"extensions":)"
                                                R"({"KHR_materials_emissive_strength":{"emissiveStrength":1e300}}}])")}},
     "render {dir}/s.gltf", "s.gltf: material '' (0): emissiveStrength x emissiveFactor is beyond float range"},
    {"glTF light intensity beyond float range",
     {{"s.gltf", R"({"asset":{"version":"2.0"},"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point",)"
                 R"("intensity":1e300}]}},"nodes":[{"extensions":{"KHR_lights_punctual":{"light":0}}}],"scenes":[{"nodes":[0]}]})"}},
     "render {dir}/s.gltf", "s.gltf: light '' (0): intensity x color is beyond float range"},
    {"glTF node hierarchy with a cycle",
     {{"s.gltf", R"({"asset":{"version":"2.0"},"nodes":[{"children":[1]},{"children":[0]}],"scenes":[{"nodes":[0]}]})"}},
     "render {dir}/s.gltf", "s.gltf: node 0 is reached twice: the node hierarchy is not a tree"},
    {"glTF GPU instances scaled by an accessor of the wrong type",
     {{"s.gltf", gltfTriangleOnNodes(R"([{"mesh":0,"extensions":{"EXT_mesh_gpu_instancing":)"
                                     R"({"attributes":{"TRANSLATION":0,"SCALE":1}}}}])")}},
     "render {dir}/s.gltf", "s.gltf: mesh '' (0) EXT_mesh_gpu_instancing: SCALE accessor 1 is not a VEC3"},
    {"glTF image buffer view running past its buffer",
     {{"s.gltf", R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":4,"uri":"data:application/octet-stream;)"
                 R"(base64,AAAAAA=="}],"bufferViews":[{"buffer":0,"byteLength":8}],"images":[{"bufferView":0,)"
                 R"("mimeType":"image/png"}]})"}},
     "render {dir}/s.gltf",
     "s.gltf: image 0: bufferView 0 (byteOffset 0, byteLength 8) runs past the end of buffer 0 (4 bytes)"},
    {"glTF 1.0 name that names nothing",
     {{"s.gltf", R"({"asset":{"version":"1.0"},"meshes":{"a":{"primitives":[{"attributes":{"POSITION":"nope"}}]}}})"}},
     "render {dir}/s.gltf", "s.gltf: glTF 1.0: mesh 'a': POSITION names accessor \"nope\", which does not exist"},
    // MTL
    {"MTL malformed Kd", {{"s.mtl", "newmtl white\nKd 0.5 abc 0.5\n"}}, "render {dir}/s.obj",
     "s.mtl:2: 'abc' is not a number"},
    {"MTL Kd before newmtl", {{"s.mtl", "Kd 0.5 0.5 0.5\n"}}, "render {dir}/s.obj",
     "s.mtl:1: 'Kd' before any newmtl"},
    {"MTL Kd above 1", {{"s.mtl", "newmtl white\nKd 1.5 0.5 0.5\n"}}, "render {dir}/s.obj",
     "s.mtl:1: material 'white' has Kd above 1"},
    {"MTL negative Ke", {{"s.mtl", "newmtl white\nKe -1 0 0\n"}}, "render {dir}/s.obj",
     "material 'white' has a negative or non-finite Kd, Ke, Ks or Pr"},
    {"MTL Ke is Inf", {{"s.mtl", "newmtl white\nKe inf 1 1\n"}}, "render {dir}/s.obj",
     "s.mtl:2: 'inf' is not a finite number"},
    // Files a scene refers to outside its folder (scene_folder.h)
    {"MTL texture outside the scene's folder", {{"s.mtl", kMtl + "map_Ke ../glow.png\n"}}, "render {dir}/s.obj",
     "s.mtl:4: map_Ke '../glow.png' resolves outside the model's folder"},
    {"OBJ mtllib outside the scene's folder", {{"s.obj", "mtllib /etc/x.mtl\n" + kObj}}, "render {dir}/s.obj",
     "s.obj:1: mtllib '/etc/x.mtl' resolves outside the model's folder"},
    {"glTF buffer outside the scene's folder", {{"s.gltf", gltfTriangle("", "", R"("/etc/passwd")")}},
     "render {dir}/s.gltf", "s.gltf: URI '/etc/passwd' resolves outside the model's folder"},
    {"scene JSON environment outside the scene's folder", {{"s.json", R"({"environment":{"file":"/dev/zero"}})"}},
     "render {dir}/s.obj", "s.json: \"environment\" file '/dev/zero' resolves outside the model's folder"},
    {"scene JSON environment not a regular file", {{"s.json", R"({"environment":{"file":"."}})"}},
     "render {dir}/s.obj", "s.json: \"environment\" file '.' is not a regular file"},
    // Scene description JSON (s.json beside s.obj)
    {"scene JSON syntax error", {{"s.json", "{\n\"position\": [0,0,\n}"}}, "render {dir}/s.obj",
     "s.json: invalid JSON: parse error at line 3"},
    {"scene JSON not an object", {{"s.json", "[1, 2, 3]"}}, "render {dir}/s.obj",
     "s.json: expected a JSON object"},
    {"scene JSON key missing", {{"s.json", R"({"position":[0,0,0]})"}}, "render {dir}/s.obj",
     "s.json: missing key \"look_at\""},
    {"scene JSON vector of strings",
     {{"s.json", R"({"position":["a",0,0],"look_at":[0,0,1],"up":[0,1,0],"fov_y":40})"}},
     "render {dir}/s.obj", "s.json: \"position\" must be an array of 3 numbers"},
    {"scene JSON value beyond float range",
     {{"s.json", R"({"position":[0,0,0],"look_at":[0,0,1],"up":[0,1,0],"fov_y":1e300})"}},
     "render {dir}/s.obj", "s.json: \"fov_y\" must be finite and within float range"},
    {"scene JSON environment of an unknown form", {{"s.json", R"({"environment":"sky"})"}}, "render {dir}/s.obj",
     "s.json: \"environment\" must be \"none\""},
    {"scene JSON environment file missing", {{"s.json", R"({"environment":{"file":"sky.exr"}})"}},
     "render {dir}/s.obj", "s.json: \"environment\" file 'sky.exr': no such file"},
    {"scene JSON environment file not an EXR",
     {{"s.json", R"({"environment":{"file":"sky.exr"}})"}, {"sky.exr", "not an image\n"}}, "render {dir}/s.obj",
     "sky.exr: not a readable EXR file"},
    {"scene JSON fov of 180",
     {{"s.json", R"({"position":[0,0,0],"look_at":[0,0,1],"up":[0,1,0],"fov_y":180})"}},
     "render {dir}/s.obj", "s.json: fov_y must be in (0, 180) degrees"},
    {"scene JSON up parallel to the view",
     {{"s.json", R"({"position":[0,0,0],"look_at":[0,1,0],"up":[0,1,0],"fov_y":40})"}},
     "render {dir}/s.obj", "s.json: up must not be parallel to the view direction"},
    {"scene JSON width 0",
     {{"s.json", R"({"position":[0,0,0],"look_at":[0,0,1],"up":[0,1,0],"fov_y":40,"width":0})"}},
     "render {dir}/s.obj", "s.json: \"width\" must be an integer in 1..65536"},
    {"scene JSON point light without intensity",
     {{"s.json", R"({"position":[0,0,0],"look_at":[0,0,1],"up":[0,1,0],"fov_y":40,"point_lights":[{"position":[0,1,0]}]})"}},
     "render {dir}/s.obj", "s.json: missing key \"intensity\""},
    {"scene JSON light of an unknown type",
     {{"s.json", R"({"lights":[{"type":"area","position":[0,1,0],"intensity":[1,1,1]}]})"}},
     "render {dir}/s.obj", "s.json: unknown light type 'area' (known: point, spot)"},
    {"scene JSON light without a type",
     {{"s.json", R"({"lights":[{"position":[0,1,0],"intensity":[1,1,1]}]})"}},
     "render {dir}/s.obj", "s.json: each of \"lights\" needs a \"type\" (known: point, spot)"},
    {"--camera file missing", {}, "render {dir}/s.obj --camera {dir}/none.json",
     "none.json: cannot open camera file"},
    // strata render options
    {"render --spp not a multiple of 24", {}, "render {dir}/s.obj --spp 25", "--spp: must be a positive multiple of 24",
     kBadUsage},
    {"render --spp 0", {}, "render {dir}/s.obj --spp 0", "--spp: must be a positive multiple of 24", kBadUsage},
    {"render --spp negative", {}, "render {dir}/s.obj --spp -5",
     "--spp: must be a positive multiple of 24 (one pass = 24 paths per pixel), got -5", kBadUsage},
    {"render --spp not a number", {}, "render {dir}/s.obj --spp many", "--spp", kBadUsage},
    {"render --depth -1", {}, "render {dir}/s.obj --depth -1", "--depth: must be in 0..100000", kBadUsage},
    {"render --sampler unknown", {}, "render {dir}/s.obj --sampler sobol", "--sampler: unknown sampler 'sobol'",
     kBadUsage},
    {"render --threads too many", {}, "render {dir}/s.obj --threads 5000", "--threads: must be in 0..1024", kBadUsage},
    {"render --threads negative", {}, "render {dir}/s.obj --threads -1", "--threads: must be in 0..1024", kBadUsage},
    {"render --seed negative", {}, "render {dir}/s.obj --seed -1",
     "--seed: must be a whole number from 0 to 18446744073709551615", kBadUsage},
    {"render --seed past 2^64 - 1", {}, "render {dir}/s.obj --seed 18446744073709551616",
     "--seed: must be a whole number from 0 to 18446744073709551615", kBadUsage},
    {"render --max-triangles negative", {}, "render {dir}/s.obj --max-triangles -1",
     "--max-triangles: must be a whole number from 0 to 18446744073709551615", kBadUsage},
    {"render --width too large", {}, "render {dir}/s.obj --width 70000", "--width: must be in 1..65536", kBadUsage},
    {"render --height negative", {}, "render {dir}/s.obj --height -4", "--height: must be in 1..65536", kBadUsage},
    {"render --epsilon 0", {}, "render {dir}/s.obj --epsilon 0", "--epsilon: must be positive", kBadUsage},
    {"render --roulette-depth -2", {}, "render {dir}/s.obj --roulette-depth -2",
     "--roulette-depth: must be -1 (off) or at least 0", kBadUsage},
    {"render --terminator-offset past 1", {}, "render {dir}/s.obj --terminator-offset 1.5",
     "--terminator-offset: must be a cosine in 0..1 (0: off)", kBadUsage},
    {"render --noise-threshold negative", {}, "render {dir}/s.obj --noise-threshold -1",
     "--noise-threshold: must be in 0..10", kBadUsage},
    {"render --tonemap unknown", {}, "render {dir}/s.obj --tonemap filmic", "--tonemap: unknown tonemap 'filmic'",
     kBadUsage},
    {"render --max-triangles 0", {}, "render {dir}/s.obj --max-triangles 0", "--max-triangles: must be at least 1",
     kBadUsage},
    {"scene over the triangle budget (OBJ)", {}, "render {dir}/s.obj --max-triangles 1",
     "s.obj: 2 triangles after instancing exceed the budget of 1 triangle (--max-triangles N raises it)"},
    {"scene over the triangle budget (glTF, one primitive placed by three nodes)",
     {{"s.gltf", gltfPlacedThrice()}},
     "render {dir}/s.gltf --max-triangles 9",
     "s.gltf: 1 triangle after instancing and 3 instances (counted as 3 triangles each; 3 triangles placed) "
     "exceed the budget of 9 triangles (--max-triangles N raises it)"},
    {"render --exposure out of range", {}, "render {dir}/s.obj --exposure 100", "--exposure: must be in -24..24 stops",
     kBadUsage},
    {"render --background unknown", {}, "render {dir}/s.obj --background sky",
     "--background: expected env|gradient|V|R,G,B (radiances finite and >= 0), got 'sky'", kBadUsage},
    {"render --background negative", {}, "render {dir}/s.obj --background 1,-1,0", "--background: expected",
     kBadUsage},
    {"render --out unknown format", {}, "render {dir}/s.obj --out {dir}/image.bmp",
     "--out: {dir}/image.bmp: unknown image format (use .exr, .pfm or .png)", kBadUsage},
    {"render --out into a missing folder", {}, "render {dir}/s.obj --spp 24 --out {dir}/no/such/dir.exr",
     "--out: {dir}/no/such/dir.exr: cannot write: no such folder {dir}/no/such"},
    {"render --out onto a folder", {}, "render {dir}/s.obj --out {dir}",
     "--out: {dir}: cannot write: it is a folder"},
    {"render unknown option", {}, "render {dir}/s.obj --frobnicate",
     "unknown option '--frobnicate' (see strata render --help)", kBadUsage},
    {"render mistyped option", {}, "render {dir}/s.obj --sp 24",
     "unknown option '--sp'; did you mean '--spp'? (see strata render --help)", kBadUsage},
    {"render two scenes", {}, "render {dir}/s.obj {dir}/s.obj", "unexpected argument '{dir}/s.obj'", kBadUsage},
    // Environment options (the maps' own checks: "environment maps" below)
    {"--env map missing", {}, "render {dir}/s.obj --env {dir}/sky.exr", "sky.exr: no such EXR file"},
    {"--env map not an EXR", {{"sky.exr", "not an image\n"}}, "render {dir}/s.obj --env {dir}/sky.exr",
     "sky.exr: not a readable EXR file"},
    {"--env-color negative", {}, "render {dir}/s.obj --env-color 1 -1 1",
     "--env-color: must be three finite radiances >= 0", kBadUsage},
    {"--env-color of two numbers", {}, "render {dir}/s.obj --env-color 1 1", "--env-color", kBadUsage},
    {"--env with --env-color", {}, "render {dir}/s.obj --env none --env-color 1 1 1", "--env excludes --env-color",
     kBadUsage},
    {"--env-rotate not finite", {}, "render {dir}/s.obj --env-rotate inf", "--env-rotate: must be a finite angle",
     kBadUsage},
    {"--env map claiming 23170 x 11585 pixels in 93 KB without pixel data", {{"sky.exr", test::forgedExr(23170, 11585)}},
     "render {dir}/s.obj --env {dir}/sky.exr",
     "sky.exr: not a readable EXR file (23170 x 11585 pixels, but chunk 1 of 11585 of their data lies outside the "
     "file's 92993 bytes: truncated or corrupt)"},
    // Texture budget
    {"texture over --texture-budget",
     {{"s.mtl", kMtl + "map_Kd t.png\n"}, {"t.png", test::pngFile(64, 64, 8, 2, std::string(64 * (1 + 64 * 3), '\0'))}},
     "render {dir}/s.obj --texture-budget 0.00001",
     "s.mtl:4: map_Kd: texture 't.png' is 64 x 64, 3 channels of 8 bits (12.0 KiB); with it the scene's textures "
     "would take 12.0 KiB, over the --texture-budget of 10.5 KiB"},
    {"--env map and textures together over --texture-budget",
     {{"s.mtl", kMtl + "map_Kd t.png\n"}, {"t.png", test::pngFile(64, 64, 8, 2, std::string(64 * (1 + 64 * 3), '\0'))},
      {"sky.exr", skyExr()}},
     "render {dir}/s.obj --env {dir}/sky.exr --texture-budget 0.0000116",
     "s.mtl:4: map_Kd: texture 't.png' is 64 x 64, 3 channels of 8 bits (12.0 KiB); with it the scene's textures "
     "would take 12.4 KiB, over the --texture-budget of 12.2 KiB"},
    {"render --texture-budget 0", {}, "render {dir}/s.obj --texture-budget 0",
     "--texture-budget: must be a positive number of GiB", kBadUsage},
    {"unknown subcommand", {}, "paint", "unknown command 'paint' (see strata --help)", kBadUsage},
    {"mistyped subcommand", {}, "rendr", "unknown command 'rendr'; did you mean 'render'?", kBadUsage},
    // strata view options (checked before any window or context opens)
    {"view --screenshot unknown format", {}, "view {dir}/s.obj --headless --frames 1 --screenshot {dir}/shot.jpg",
     "--screenshot: {dir}/shot.jpg: unknown image format", kBadUsage},
    {"view --screenshot not a PNG", {}, "view {dir}/s.obj --headless --frames 1 --screenshot {dir}/shot.exr",
     "--screenshot: {dir}/shot.exr: must be a .png file", kBadUsage},
    {"view --screenshot into a missing folder", {},
     "view {dir}/s.obj --headless --frames 1 --screenshot {dir}/no/shot.png",
     "--screenshot: {dir}/no/shot.png: cannot write: no such folder {dir}/no"},
    {"view --scale out of range", {}, "view {dir}/s.obj --headless --frames 1 --scale 2", "--scale: must be in 0.05..1",
     kBadUsage},
    // strata samples options
    {"samples --passes 0", {}, "samples --passes 0", "--passes: must be in 1..1000000", kBadUsage},
    {"samples --passes negative", {}, "samples --passes -3", "--passes", kBadUsage},
    {"samples --seed negative", {}, "samples --seed -2", "--seed: must be a whole number", kBadUsage},
    {"samples --depth 0", {}, "samples --depth 0", "--depth: must be in 1..64", kBadUsage},
    {"samples --sampler unknown", {}, "samples --sampler halton", "--sampler: unknown sampler 'halton'", kBadUsage},
    {"samples --pixel not a number", {}, "samples --pixel x", "--pixel", kBadUsage},
    {"samples mistyped option", {}, "samples --pases 2", "unknown option '--pases'; did you mean '--passes'?",
     kBadUsage},
    // strata bench options (checked before any run)
    {"bench --only unknown section", {}, "bench --only colours --out-dir {dir}/out",
     "--only: unknown section 'colours' (use errors|throughput|embree|cycles|viewer|real-scenes|ranks)", kBadUsage},
    {"bench --max-spp negative", {}, "bench --max-spp -24 --out-dir {dir}/out",
     "--max-spp: must be a positive multiple of 24", kBadUsage},
    {"bench --threads negative", {}, "bench --threads -2 --out-dir {dir}/out", "--threads: must be in 0..1024",
     kBadUsage},
    {"bench --seed not whole", {}, "bench --seed 1.5 --out-dir {dir}/out", "--seed: must be a whole number",
     kBadUsage},
    {"bench --max-seconds 0", {}, "bench --max-seconds 0 --out-dir {dir}/out", "--max-seconds: must be in (0, 1e7]",
     kBadUsage},
    {"bench mistyped option", {}, "bench --quik --out-dir {dir}/out", "unknown option '--quik'; did you mean '--quick'?",
     kBadUsage},
    {"bench --out-dir onto a file", {}, "bench --quick --out-dir {dir}/s.obj",
     "--out-dir: {dir}/s.obj: cannot create the folder"},
};

// Input that other tools open: it renders, with one "warning: " line for each thing tolerated.
struct ToleratedCase {
    const char* what;  // the case, as docs/reliability.md describes it
    std::map<std::string, std::string> files;
    std::vector<std::string> warnings;  // each printed as "warning: {dir}/..."
    const char* summary;                // text the load summary line must contain
};

const std::string kQuad = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\n";
const std::vector<ToleratedCase> kToleratedCases = {
    {"OBJ usemtl of an undefined material",
     {{"s.obj", "mtllib s.mtl\n" + kQuad + "usemtl red\nf 1 3 2\nusemtl white\nf 1 4 3\n"}},
     {"s.obj:6: material 'red' is not defined; using grey Kd 0.8"}, "1 emitting (area 0.5), max albedo 0.8"},
    {"OBJ usemtl without a name",
     {{"s.obj", "mtllib s.mtl\n" + kQuad + "usemtl\nf 1 3 2\nusemtl white\nf 1 4 3\n"}},
     {"s.obj:6: usemtl names no material; using grey Kd 0.8"}, "extent 1 x 0 x 1, 1 warning\n"},
    {"OBJ mtllib file missing",
     {{"s.obj", "mtllib gone.mtl\n" + kQuad + "usemtl white\nf 1 3 2\nf 1 4 3\n"}},
     {"s.obj:1: material library 'gone.mtl' is missing; its materials are not defined",
      "s.obj:6: material 'white' is not defined; using grey Kd 0.8"},
     "0 emitting (area 0), max albedo 0.8, 0 point lights, fast triangle test (rounding gap share 4.1e-07), extent 1 x 0 x 1, 2 warnings"},
    {"OBJ and MTL material name with spaces",
     {{"s.obj", "mtllib s.mtl\n" + kQuad + "usemtl  white light \nf 1 3 2\nf 1 4 3\n"},
      {"s.mtl", "newmtl white light\nKd 0.5 0.5 0.5\nKe 1 1 1\n"}},
     {}, "2 emitting (area 1)"},
    {"OBJ normal of zero length",
     {{"s.obj", "mtllib s.mtl\n" + kQuad + "vn 0 0 0\nvn 0 1 0\nusemtl white\nf 1//1 3//2 2//2\nf 1//2 4//2 3//2\n"}},
     {"s.obj:6: vn is zero or not finite; 1 triangle using such a normal is shaded flat"}, "2 emitting"},
    {"MTL newmtl without a name, texture maps with options, statements not used",
     {{"s.mtl", "newmtl\nKd 1 1 1\nnewmtl white\nKd 0.5 0.5 0.5\nKe 1 1 1\nKa 1 1 1\nTf 1 1 1\nNi 1.5\n"
                "d 1\nTr 0\nillum 2\nmap_Kd -bm 1.0 -s 1 1 1 wood.png\nmap_d a.png\nmap_Ke e.png\n"
                "norm n.png\nmap_Bump -bm 0.5 b.png\nbump b.png\n"}},
     {"s.mtl:12: map_Kd: texture file 'wood.png' is missing; using the factor alone",
      "s.mtl:13: map_d: texture file 'a.png' is missing; using the factor alone",
      "s.mtl:14: map_Ke: texture file 'e.png' is missing; using the factor alone",
      "s.mtl:15: norm: texture file 'n.png' is missing; using the factor alone",
      "s.mtl:16: map_Bump: texture file 'b.png' is missing; using the factor alone",
      "s.mtl:17: bump: texture file 'b.png' is missing; using the factor alone"},
     "2 emitting (area 1), max albedo 0.5, 0 point lights, fast triangle test (rounding gap share 4.1e-07), extent 1 x 0 x 1, 6 warnings\n"},
    {"MTL texture that does not decode",
     {{"s.mtl", "newmtl white\nKd 0.5 0.5 0.5\nKe 1 1 1\nmap_Kd bad.png\n"}, {"bad.png", "\x89PNG\r\n\x1a\nbroken"}},
     {"s.mtl:4: map_Kd: bad.png: cannot decode the texture (unknown image type); using the factor alone"},
     "2 emitting"},
    {"MTL texture: a GIF claiming 16384 x 16384 pixels in 40 KB",
     {{"s.mtl", "newmtl white\nKd 0.5 0.5 0.5\nKe 1 1 1\nmap_Kd big.gif\n"}, {"big.gif", test::forgedGif(16384, 16384, 40000)}},
     {"s.mtl:4: map_Kd: big.gif: a 16384 x 16384 image cannot be stored in 40000 bytes (truncated or corrupt); using "
      "the factor alone"},
     "2 emitting"},
    {"MTL texture: a JPEG claiming 16384 x 16384 pixels in 40 KB",
     {{"s.mtl", "newmtl white\nKd 0.5 0.5 0.5\nKe 1 1 1\nmap_Kd big.jpg\n"}, {"big.jpg", test::forgedJpeg(16384, 16384, 40960)}},
     {"s.mtl:4: map_Kd: big.jpg: a 16384 x 16384 image cannot be stored in 40960 bytes (truncated or corrupt); using "
      "the factor alone"},
     "2 emitting"},
    {"MTL texture: a truncated JPEG",
     {{"s.mtl", "newmtl white\nKd 0.5 0.5 0.5\nKe 1 1 1\nmap_Kd cut.jpg\n"}, {"cut.jpg", test::truncatedJpeg()}},
     {"s.mtl:4: map_Kd: cut.jpg: damaged or truncated JPEG (libjpeg: Corrupt JPEG data: premature end of data segment)"},
     "2 emitting"},
    {"MTL texture whose header claims more texels than its file holds",
     {{"s.mtl", "newmtl white\nKd 0.5 0.5 0.5\nKe 1 1 1\nmap_Kd t.tga\n"}, {"t.tga", test::forgedTga()}},
     {"s.mtl:4: map_Kd: t.tga: a 2608 x 29814 image cannot be stored in 26 bytes (truncated or corrupt); using "
      "the factor alone"},
     "2 emitting"},
};


std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
        text.replace(at, from.size(), to);
    }
    return text;
}

}  // namespace

TEST_CASE("bad input: every case is one 'strata:' line naming the culprit, a non-zero exit, no clobbering") {
    int index = 0;
    for (const BadInputCase& c : kCliCases) {
        const std::string what = c.what;
        CAPTURE(what);
        const auto dir = test::scratchDir("bad-input-" + std::to_string(index++));
        std::map<std::string, std::string> files = {{"s.obj", kObj}, {"s.mtl", kMtl}, {"s.json", kCamera}};
        for (const auto& [name, text] : c.files) files[name] = text;
        for (const auto& [name, text] : files) std::ofstream(dir / name, std::ios::binary) << text;
        // An earlier result that a failed render must leave as it was.
        const std::string precious = "an earlier render\n";
        std::ofstream(dir / "keep.exr", std::ios::binary) << precious;

        std::string arguments = replaceAll(c.arguments, "{dir}", dir.string());
        // Render cases write over keep.exr if they get that far, and take one pass.
        if (arguments.rfind("render", 0) == 0) {
            if (arguments.find("--out") == std::string::npos) arguments += " --out " + (dir / "keep.exr").string();
            if (arguments.find("--spp") == std::string::npos) arguments += " --spp 24";
        }
        const test::CommandResult result = test::runStrata(arguments);
        CAPTURE(arguments);
        CAPTURE(result.err);
        CHECK(result.exitCode == c.exitStatus);  // 1 for bad input, 2 for bad usage; never a signal
        // Exactly one line says what is wrong, and it is the last thing printed.
        std::vector<std::string> errorLines;
        std::istringstream lines(result.err);
        std::string lastLine;
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("strata: ", 0) == 0) errorLines.push_back(line);
            if (!line.empty()) lastLine = line;
        }
        REQUIRE(errorLines.size() == 1);
        CHECK(errorLines[0] == lastLine);
        CHECK(errorLines[0].find(replaceAll(c.expected, "{dir}", dir.string())) != std::string::npos);
        CHECK(test::fileBytes(dir / "keep.exr") == precious);
        // No temporary file left behind either.
        size_t entries = 0;
        for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++entries;
        CHECK(entries == files.size() + 1);
        std::filesystem::remove_all(dir);
    }
}

TEST_CASE("bad input: the valid scene of the table renders, and over an existing output") {
    // The table's base scene is good, so each case fails for its own reason alone.
    const auto dir = test::scratchDir("bad-input-good");
    std::ofstream(dir / "s.obj") << kObj;
    std::ofstream(dir / "s.mtl") << kMtl;
    std::ofstream(dir / "s.json") << kCamera;
    std::ofstream(dir / "keep.exr") << "an earlier render\n";
    const auto result = test::runStrata("render " + (dir / "s.obj").string() + " --spp 24 --depth 1 --out " +
                                        (dir / "keep.exr").string());
    CAPTURE(result.err);
    CHECK(result.exitCode == 0);
    const Image image = readExr(dir / "keep.exr");
    CHECK(image.width == 4);
    CHECK(image.height == 4);
    std::filesystem::remove_all(dir);
}

TEST_CASE("bad input: EXR references that are missing, empty, not EXR or truncated are refused") {
    const auto dir = test::scratchDir("bad-exr");
    Image good{8, 8, std::vector<glm::vec3>(64, glm::vec3(0.25f))};
    writeImage(dir / "good.exr", good);
    const std::string bytes = test::fileBytes(dir / "good.exr");
    std::ofstream(dir / "empty.exr", std::ios::binary) << "";
    std::ofstream(dir / "text.exr", std::ios::binary) << "P3 this is not an EXR\n";
    std::ofstream(dir / "truncated.exr", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    std::ofstream(dir / "header.exr", std::ios::binary) << bytes.substr(0, 40);
    std::string corrupt = bytes;
    for (size_t i = bytes.size() / 2; i < bytes.size(); i += 7) corrupt[i] = static_cast<char>(~corrupt[i]);
    std::ofstream(dir / "corrupt.exr", std::ios::binary) << corrupt;
    std::filesystem::create_directories(dir / "folder.exr");

    const struct {
        const char* file;
        const char* expected;
    } cases[] = {{"absent.exr", "absent.exr: no such EXR file"},
                 {"folder.exr", "folder.exr: no such EXR file"},
                 {"empty.exr", "empty.exr: not a readable EXR file"},
                 {"text.exr", "text.exr: not a readable EXR file"},
                 {"truncated.exr", "truncated.exr: not a readable EXR file"},
                 {"header.exr", "header.exr: not a readable EXR file"},
                 {"corrupt.exr", "corrupt.exr: not a readable EXR file"}};
    for (const auto& c : cases) {
        const std::string file = c.file;
        CAPTURE(file);
        std::string message = "no error";
        try {
            readExr(dir / c.file);
        } catch (const Error& e) {
            message = e.what();
        }
        CHECK(message.find(c.expected) != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
    }
    CHECK(readExr(dir / "good.exr").pixels[63] == glm::vec3(0.25f));
    std::filesystem::remove_all(dir);
}

TEST_CASE("bad input: environment maps that are not 2:1 or hold negative or non-finite texels are refused") {
    const auto dir = test::scratchDir("bad-environment");
    std::ofstream(dir / "s.obj") << kObj;
    std::ofstream(dir / "s.mtl") << kMtl;
    std::ofstream(dir / "s.json") << kCamera;
    Image good{8, 4, std::vector<glm::vec3>(32, glm::vec3(0.5f))};
    writeImage(dir / "good.exr", good);
    writeImage(dir / "square.exr", Image{4, 4, std::vector<glm::vec3>(16, glm::vec3(0.5f))});
    Image negative = good;
    negative.pixels[9].y = -0.5f;
    writeImage(dir / "negative.exr", negative);
    Image nan = good;
    nan.pixels[31].x = NAN;
    writeImage(dir / "nan.exr", nan);
    const struct {
        const char* file;
        const char* expected;
    } cases[] = {{"square.exr", "square.exr: an environment map must be a latitude-longitude image twice as wide as high, got 4x4"},
                 {"negative.exr", "negative.exr: texel (1, 1) is negative beyond lossy-compression noise"},
                 {"nan.exr", "nan.exr: texel (7, 3) is not finite"}};
    const std::string scene = (dir / "s.obj").string();
    for (const auto& c : cases) {
        CAPTURE(c.file);
        const auto result = test::runStrata("render " + scene + " --spp 24 --env " + (dir / c.file).string());
        CAPTURE(result.err);
        CHECK(result.exitCode == 1);
        CHECK(result.err.rfind("strata: ", 0) == 0);
        CHECK(result.err.find(c.expected) != std::string::npos);
        CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
    }
    const auto lit = test::runStrata("render " + scene + " --spp 24 --env " + (dir / "good.exr").string());
    CAPTURE(lit.err);
    CHECK(lit.exitCode == 0);
}

TEST_CASE("bad input: tolerated input renders, each warning one line naming the file and line") {
    int index = 0;
    for (const ToleratedCase& c : kToleratedCases) {
        const std::string what = c.what;
        CAPTURE(what);
        const auto dir = test::scratchDir("tolerated-input-" + std::to_string(index++));
        std::map<std::string, std::string> files = {{"s.obj", kObj}, {"s.mtl", kMtl}, {"s.json", kCamera}};
        for (const auto& [name, text] : c.files) files[name] = text;
        for (const auto& [name, text] : files) std::ofstream(dir / name, std::ios::binary) << text;
        const test::CommandResult result = test::runStrata("render " + (dir / "s.obj").string() + " --spp 24");
        CAPTURE(result.err);
        CHECK(result.exitCode == 0);
        std::vector<std::string> warnings;
        std::istringstream lines(result.err);
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("warning: ", 0) == 0) warnings.push_back(line);
        }
        std::vector<std::string> expected;
        for (const std::string& warning : c.warnings) expected.push_back("warning: " + (dir / warning).string());
        CHECK(warnings == expected);
        CHECK(result.err.find(c.summary) != std::string::npos);
    }
}
