#include "bench/cycles_script.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "util/error.h"

namespace strata {
namespace {

constexpr std::string_view kSecondsLabel = "cycles render seconds: ";

// Every setting below is one that made Cycles' image differ from Strata's, or is a factory
// default that biases Cycles (clamping, glossy blur, light threshold, denoising, adaptive
// sampling, a wide pixel filter, bounce caps per kind).
constexpr std::string_view kScript = R"python(# Renders an OBJ scene with Blender's Cycles as Strata renders it (strata bench --vs-cycles).
# blender -b --factory-startup --python-exit-code 1 --python cycles_render.py -- PARAMETERS.json
import json
import math
import sys
import time

import bpy
from mathutils import Matrix, Vector

parameters_file = sys.argv[sys.argv.index("--") + 1]
with open(parameters_file) as f:
    params = json.load(f)
scale = params["scale"]

# --factory-startup still holds a cube, a light and a grey world: start from nothing.
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

# Cycles 3.4 samples triangle lights by solid angle with an approximate acos that makes small ones
# too dark in a scene measured in millimetres; radiance does not depend on scale, so the scene is
# made unit size (the camera below too).
# The importer turns OBJ (x, y, z) into (x, -z, y) by default; these axes keep them as they are.
bpy.ops.wm.obj_import(filepath=params["model"], forward_axis='Y', up_axis='Z', global_scale=scale)


def linear_image(path):
    """An EXR the bench decoded with Strata's own code: its floats are the radiance or albedo."""
    image = bpy.data.images.load(path)
    image.colorspace_settings.name = 'Linear'
    return image


def surface(material, spec):
    """Strata's material as Cycles nodes: diffuse Kd times the linear texture (MTL's map_Kd
    multiplies Kd; Blender's importer would replace it), or GGX with Ks and roughness Pr (Cycles
    squares its roughness input as Strata squares Pr), plus radiance Ke from the front
    (counter-clockwise) side only: Cycles' mesh emission is two-sided, Strata's Ke one-sided."""
    material.use_nodes = True
    nodes = material.node_tree.nodes
    links = material.node_tree.links
    nodes.clear()
    if any(spec["ks"]):
        reflection = nodes.new("ShaderNodeBsdfGlossy")
        reflection.distribution = 'GGX'
        reflection.inputs["Color"].default_value = (*spec["ks"], 1.0)
        reflection.inputs["Roughness"].default_value = spec["roughness"]
    else:
        reflection = nodes.new("ShaderNodeBsdfDiffuse")
        reflection.inputs["Color"].default_value = (*spec["kd"], 1.0)
        reflection.inputs["Roughness"].default_value = 0.0
    if spec["texture"]:
        # Strata's lookup: bilinear between texel centres, repeating outside [0, 1).
        texture = nodes.new("ShaderNodeTexImage")
        texture.image = linear_image(spec["texture"])
        texture.interpolation = 'Linear'
        texture.extension = 'REPEAT'
        times_kd = nodes.new("ShaderNodeVectorMath")
        times_kd.operation = 'MULTIPLY'
        times_kd.inputs[1].default_value = spec["kd"]
        links.new(texture.outputs["Color"], times_kd.inputs[0])
        links.new(times_kd.outputs["Vector"], reflection.inputs["Color"])
    geometry = nodes.new("ShaderNodeNewGeometry")
    front = nodes.new("ShaderNodeMath")
    front.operation = 'SUBTRACT'
    front.inputs[0].default_value = 1.0
    links.new(geometry.outputs["Backfacing"], front.inputs[1])
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (*spec["ke"], 1.0)
    links.new(front.outputs["Value"], emission.inputs["Strength"])
    add = nodes.new("ShaderNodeAddShader")
    links.new(reflection.outputs["BSDF"], add.inputs[0])
    links.new(emission.outputs["Emission"], add.inputs[1])
    output = nodes.new("ShaderNodeOutputMaterial")
    links.new(add.outputs["Shader"], output.inputs["Surface"])


# Cycles offsets shadow rays from a smoothly shaded triangle toward the surface its vertex normals
# describe (the shadow terminator's geometry offset, 0.1 by factory default), which lights the
# faceted terminator under a small bright source; Strata traces them from the triangle itself.
for mesh_object in scene.objects:
    mesh_object.cycles.shadow_terminator_geometry_offset = 0.0
    mesh_object.cycles.shadow_terminator_offset = 0.0

materials = params["materials"]
for material in bpy.data.materials:
    # Importers number repeated names (NAME.001) where Strata keeps the name.
    name = material.name if material.name in materials else material.name.rsplit(".", 1)[0]
    if name not in materials:
        raise RuntimeError("the model's material '%s' is not in %s" % (material.name, parameters_file))
    surface(material, materials[name])

# A uniform sky of radiance `sky` (Strata's --env-color), or black, or a latitude-longitude map
# along the ray's direction, its texels constant as Strata's are (the scene is turned below so
# that Cycles' convention reads Strata's texel); how Cycles samples the world is left at its
# factory setting (automatic: an importance map of the image's resolution).
world = bpy.data.worlds.new("sky")
world.use_nodes = True
background = world.node_tree.nodes["Background"]
background.inputs["Color"].default_value = (*params["sky"], 1.0)
background.inputs["Strength"].default_value = 1.0
environment = params["environment"]
if environment:
    map_node = world.node_tree.nodes.new("ShaderNodeTexEnvironment")
    map_node.image = linear_image(environment["file"])
    map_node.interpolation = 'Closest'
    map_node.projection = 'EQUIRECTANGULAR'
    world.node_tree.links.new(map_node.outputs["Color"], background.inputs["Color"])
scene.world = world

# Strata's pinhole looks from position at look_at, right = forward x up, fov_y the vertical field
# of view (renderer/scene/camera.cpp); Blender's camera looks down its -Z with +Y up.
position = Vector(params["position"]) * scale
forward = (Vector(params["look_at"]) * scale - position).normalized()
right = forward.cross(Vector(params["up"])).normalized()
up = right.cross(forward)
camera_data = bpy.data.cameras.new("camera")
camera_data.sensor_fit = 'VERTICAL'
camera_data.angle_y = math.radians(params["fov_y"])
camera_data.clip_start = 1e-4
camera_data.clip_end = 1e4
camera = bpy.data.objects.new("camera", camera_data)
scene.collection.objects.link(camera)
camera.matrix_world = Matrix((
    (right.x, up.x, -forward.x, position.x),
    (right.y, up.y, -forward.y, position.y),
    (right.z, up.z, -forward.z, position.z),
    (0.0, 0.0, 0.0, 1.0)))
scene.camera = camera

# Under a map, the whole scene, camera included, is turned by `frame`: a rotation, so the image
# is the same, and Cycles' lookup of a turned direction reads the texel Strata reads along the
# unturned one.
if environment:
    frame = Matrix(environment["frame"]).to_4x4()
    for root in [o for o in scene.objects if o.parent is None]:
        root.matrix_world = frame @ root.matrix_world

render = scene.render
render.engine = 'CYCLES'
render.resolution_x = params["width"]
render.resolution_y = params["height"]
render.resolution_percentage = 100
render.pixel_aspect_x = 1.0
render.pixel_aspect_y = 1.0
render.threads_mode = 'FIXED'
render.threads = params["threads"]
render.dither_intensity = 0.0
render.film_transparent = False
scene.view_settings.view_transform = 'Standard'
scene.view_settings.look = 'None'
scene.view_settings.exposure = 0.0
scene.view_settings.gamma = 1.0
render.image_settings.file_format = 'OPEN_EXR'
render.image_settings.color_mode = 'RGB'
render.image_settings.color_depth = '32'
render.image_settings.exr_codec = 'ZIP'

cycles = scene.cycles
cycles.device = 'CPU'
cycles.samples = params["spp"]
cycles.seed = params["seed"]
cycles.use_adaptive_sampling = False
cycles.use_denoising = False
cycles.sample_clamp_direct = 0.0
cycles.sample_clamp_indirect = 0.0
cycles.blur_glossy = 0.0
cycles.light_sampling_threshold = 0.0
cycles.caustics_reflective = True
cycles.caustics_refractive = True
# One cap for every kind of bounce (the factory caps diffuse and glossy bounces at 4).
for cap in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
            "transparent_max_bounces"):
    setattr(cycles, cap, params["max_bounces"])
# Strata jitters each sample uniformly over its pixel: a box filter one pixel wide.
cycles.pixel_filter_type = 'BOX'
cycles.filter_width = 1.0

start = time.perf_counter()
bpy.ops.render.render()
seconds = time.perf_counter() - start
bpy.data.images["Render Result"].save_render(params["out"])
print("cycles render seconds: %.6f" % seconds, flush=True)
)python";

nlohmann::json triple(float x, float y, float z) { return nlohmann::json::array({x, y, z}); }

}  // namespace

std::string_view cyclesScript() { return kScript; }

std::string cyclesParameters(const CyclesJob& job) {
    nlohmann::json materials = nlohmann::json::object();
    for (const Material& m : job.materials) {
        const auto texture = job.colourTextures.find(m.name);
        const bool textured = texture != job.colourTextures.end();
        materials[m.name] = {
            {"kd", triple(m.diffuse.x, m.diffuse.y, m.diffuse.z)},
            {"ke", triple(m.emission.x, m.emission.y, m.emission.z)},
            {"ks", triple(m.specular.x, m.specular.y, m.specular.z)},
            {"roughness", m.roughness},
            {"texture", textured ? std::filesystem::absolute(texture->second).string() : std::string()}};
    }
    nlohmann::json environment = nullptr;
    if (!job.environmentMap.empty()) {
        const glm::mat3& m = job.environmentFrame;  // glm is column-major: rows written out
        environment = {{"file", std::filesystem::absolute(job.environmentMap).string()},
                       {"frame", {triple(m[0][0], m[1][0], m[2][0]), triple(m[0][1], m[1][1], m[2][1]),
                                  triple(m[0][2], m[1][2], m[2][2])}}};
    }
    const CameraPose& pose = job.pose;
    const nlohmann::json parameters = {
        {"model", std::filesystem::absolute(job.model).string()},
        {"scale", job.scale},
        {"materials", materials},
        {"sky", triple(job.sky.x, job.sky.y, job.sky.z)},
        {"environment", environment},
        {"position", triple(pose.position.x, pose.position.y, pose.position.z)},
        {"look_at", triple(pose.lookAt.x, pose.lookAt.y, pose.lookAt.z)},
        {"up", triple(pose.up.x, pose.up.y, pose.up.z)},
        {"fov_y", pose.fovYDegrees},
        {"width", job.width},
        {"height", job.height},
        {"spp", job.spp},
        {"max_bounces", job.maxBounces},
        {"threads", job.threads},
        {"seed", job.seed},
        {"out", std::filesystem::absolute(job.out).string()}};
    return parameters.dump(2) + "\n";
}

std::vector<std::string> cyclesCommandLine(const std::filesystem::path& script,
                                           const std::filesystem::path& parameters) {
    return {"blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python",
            script.string(), "--", parameters.string()};
}

int cyclesMaxBounces(int strataDepth) {
    if (strataDepth < 1) {
        throw Error("--depth " + std::to_string(strataDepth) +
                    ": Cycles follows every path through at least one bounce (depth >= 1)");
    }
    return strataDepth - 1;
}

double cyclesUnitScale(const MeshData& mesh) {
    if (mesh.positions.empty()) return 1.0;
    glm::vec3 lo = mesh.positions.front(), hi = lo;
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double side = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    return side > 0.0 ? 1.0 / side : 1.0;
}

std::optional<double> parseCyclesSeconds(std::string_view log) {
    std::optional<double> seconds;
    size_t start = 0;
    while (start < log.size()) {
        const size_t end = std::min(log.find('\n', start), log.size());
        const std::string_view line = log.substr(start, end - start);
        start = end + 1;
        if (line.substr(0, kSecondsLabel.size()) != kSecondsLabel) continue;
        const std::string_view number = line.substr(kSecondsLabel.size());
        double value = 0.0;
        const auto [rest, error] = std::from_chars(number.data(), number.data() + number.size(), value);
        const bool whole = rest == number.data() + number.size() ||
                           std::string_view(rest, number.data() + number.size() - rest) == "\r";
        if (error == std::errc() && whole && std::isfinite(value) && value >= 0.0) seconds = value;
    }
    return seconds;
}

}  // namespace strata
