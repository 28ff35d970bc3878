#pragma once
// The camera a scene gets when neither a --camera file, nor its description, nor its own file
// (a glTF camera) gives one: the view a model viewer opens with.
//
// It looks at the centre of the bounding sphere (the world bounding box's centre, mesh.h's
// worldBounds; radius half its diagonal), from far enough that the whole sphere is in the frame
// (vertically, so for any image at least as wide as high), with the model's up axis up
// (model_orientation.h):
//   - a three-quarter view: from kAzimuthDegrees off the model's front toward its side
//     (up x front, the viewer's right of a model facing it) and kElevationDegrees above;
//   - a flat model (every vertex within 1% of the sphere's radius of the plane of its largest
//     triangle) head-on from its face side: the side its triangles' area-weighted normals point
//     to (counter-clockwise = front), or, when they cancel, the side the three-quarter view is
//     on. Its up is the model's up made normal to the view, or, for a model lying within about
//     6 degrees of horizontal, the model's back (a plan seen from above). A model with shared
//     meshes gets the three-quarter view: its placed triangles, which may number billions, are
//     not searched for a plane.
#include "scene/camera.h"
#include "scene/mesh.h"
#include "scene/model_orientation.h"

namespace strata {

inline constexpr float kDefaultFovYDegrees = 40.0f;
inline constexpr float kAzimuthDegrees = 40.0f;
inline constexpr float kElevationDegrees = 25.0f;

// The pose above for `mesh`, which needs at least one triangle.
CameraPose defaultCameraPose(const MeshData& mesh, const ModelOrientation& orientation);

}  // namespace strata
