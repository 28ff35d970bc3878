#pragma once
// Blender's Cycles as `strata bench --vs-cycles` runs it: the Python script that builds the scene
// in an empty Blender exactly as Strata renders it, the parameters it reads, the command line, and
// the render time it prints. The script is compiled into the program (and written into the
// bench's output folder for each run), so an installed strata needs no data file to find and the
// script always speaks the parameters this program writes.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <glm/mat3x3.hpp>

#include "materials/material.h"
#include "scene/camera.h"
#include "scene/mesh.h"

namespace strata {

struct CyclesJob {
    std::filesystem::path model;  // OBJ, or glTF (.gltf, .glb)
    // Blender scales the scene and camera by this inside (cyclesUnitScale); radiance is scale-free.
    double scale = 1.0;
    // Found by name in the model's; diffuse Kd (times its texture), or GGX Ks at roughness Pr
    // when Ks is not zero; Ke on the front side.
    std::vector<Material> materials;
    // Each textured material's colour texture as a linear float EXR (writeLinearTexture).
    std::map<std::string, std::filesystem::path> colourTextures;
    glm::vec3 sky{0.0f};              // the world's uniform radiance (black: the emitters alone)
    // A latitude-longitude map (linear float EXR) in place of `sky` when not empty, looked up by
    // Cycles along environmentFrame times the direction (cyclesEnvironmentFrame).
    std::filesystem::path environmentMap;
    glm::mat3 environmentFrame{1.0f};
    CameraPose pose;
    int width = 256;
    int height = 256;
    int spp = 64;
    int maxBounces = 8;  // Cycles' max_bounces: cyclesMaxBounces(Strata's depth)
    int threads = 1;
    uint64_t seed = 0;
    std::filesystem::path out;  // the linear float EXR it writes
};

// The Python script (blender -b --python SCRIPT -- PARAMETERS.json).
std::string_view cyclesScript();

// The JSON the script reads: the job's fields under the names the script uses.
std::string cyclesParameters(const CyclesJob& job);

// The Blender command line that runs `script` on `parameters`; a Python error exits non-zero.
std::vector<std::string> cyclesCommandLine(const std::filesystem::path& script,
                                           const std::filesystem::path& parameters);

// Cycles' max_bounces B ends a path after B + 1 reflections; Strata's depth K after K, so
// B = K - 1. Throws strata::Error for K < 1, which Cycles cannot express.
int cyclesMaxBounces(int strataDepth);

// 1 / the largest side of the mesh's bounding box: the scale that makes the scene unit size
// (Cycles 3.4's solid-angle sampling of small triangle lights is too dark in millimetre units).
double cyclesUnitScale(const MeshData& mesh);

// The seconds `bpy.ops.render.render()` took, as the script prints them ("cycles render seconds:
// S" on a line of its own), from Blender's whole output; nullopt when the line is missing or
// holds no finite non-negative number.
std::optional<double> parseCyclesSeconds(std::string_view log);

}  // namespace strata
