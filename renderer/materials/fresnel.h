#pragma once
// How much light an interface reflects and where the rest goes: Schlick's approximation for the
// layered and conductor models, the exact Fresnel equations of a dielectric for unpolarised light,
// and the mirror and refraction directions. Directions are unit vectors pointing away from the
// surface (wo toward the viewer, wi toward the light), in the local frame (normal +z) unless a
// normal is given.
#include <optional>
#include <glm/vec3.hpp>

namespace strata {

// Schlick's F0 + (1 - F0)(1 - cos)^5, per colour channel.
glm::vec3 schlickFresnel(const glm::vec3& f0, float cosine);
float schlickFresnel(float f0, float cosine);

// The reflectance of a smooth interface between two dielectrics for unpolarised light, the mean
// of the s and p Fresnel equations. `eta` is the index of refraction below the normal over the one
// above it; `cosThetaI` is signed: a negative cosine is light arriving from below (eta is then
// inverted). 1 under total internal reflection.
float dielectricFresnel(float cosThetaI, float eta);

// The mirror direction of w about the normal +z / about the unit normal n.
inline glm::vec3 reflectLocal(const glm::vec3& w) { return {-w.x, -w.y, w.z}; }
glm::vec3 reflect(const glm::vec3& w, const glm::vec3& n);

// The refracted direction of wi through an interface with unit normal n on wi's side (n.wi > 0),
// `eta` the index on the far side over wi's side; empty under total internal reflection.
std::optional<glm::vec3> refract(const glm::vec3& wi, const glm::vec3& n, float eta);

}  // namespace strata
