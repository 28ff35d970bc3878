#pragma once
// Which way a model stands: the axis that points up and the horizontal direction its front faces,
// which the default camera (default_camera.h) looks from.
//
// glTF fixes both (glTF 2.0, "Coordinate System and Units"): +Y up, the front facing +Z. OBJ states
// neither, so they are read from the model:
//   - Up is +Y (what OBJ exporters write by default) unless the model is clearly Z-up: its
//     bounding box rests on the plane z = 0 (the lowest z within 1% of the box's largest extent
//     of 0) and not on y = 0 (the lowest y farther from 0 than that). Modelling tools put a
//     model's origin at its base, so the base plane tells the up axis; a model centred on the
//     origin, or touching both planes, keeps +Y.
//   - The front is the horizontal axis direction toward which the mean of the triangles'
//     centroids lies from the area-weighted centroid, when that offset is at least 5% of the
//     model's extent along the axis (the larger of the two axes' offsets): finely tessellated
//     parts (a head, a face, the contents of a box's open side) pull the first, large plain
//     surfaces (a flank, a back wall) the second. Otherwise the front is +Z for a Y-up model and
//     -Y for a Z-up one (where 3ds Max's and Blender's front views look from).
#include <glm/vec3.hpp>

#include "scene/mesh.h"

namespace strata {

struct ModelOrientation {
    glm::vec3 up{0.0f, 1.0f, 0.0f};     // unit, along a coordinate axis
    glm::vec3 front{0.0f, 0.0f, 1.0f};  // unit, along a coordinate axis normal to `up`
};

// glTF's orientation, and the default for a format that states one.
inline constexpr ModelOrientation kGltfOrientation{};

// The orientation of an OBJ model by the rules above (glTF's for a mesh without triangles).
ModelOrientation objOrientation(const MeshData& mesh);

}  // namespace strata
