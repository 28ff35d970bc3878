#pragma once
// glTF 2.0 cameras ("Cameras") and KHR_lights_punctual lights, each at its node's world transform.
#include <optional>
#include <vector>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scene/camera.h"
#include "scene/gltf_model.h"
#include "scene/mesh.h"

namespace strata {

// The camera `index` at `world` (perspective or orthographic) into `camera` unless one is there
// already (the first reached wins); a degenerate one is a warning.
void takeGltfCamera(GltfModel& gltf, int index, const glm::dmat4& world, std::optional<CameraPose>& camera);

// Moves the look-at point straight ahead to the distance of the scene's centre.
void aimGltfCameraAtScene(CameraPose& pose, const MeshData& mesh);

// The KHR_lights_punctual light `index` at `world`, appended to the mesh's lights.
void addGltfLight(GltfModel& gltf, int index, const glm::dmat4& world, MeshData& mesh);

}  // namespace strata
