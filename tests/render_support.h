#pragma once
// Rendering small images in tests and judging them statistically: per-pixel means with their
// standard errors, and the comparisons the stress tests share.
#include <cstdint>
#include <random>
#include <vector>
#include <glm/vec3.hpp>

#include "film/accumulation_buffer.h"
#include "scene/camera.h"
#include "scene/mesh.h"
#include "integrator/progressive_renderer.h"
#include "lights/environment.h"
#include "scene/scene.h"

namespace strata::test {

// Renders `passes` whole passes into a fresh buffer.
AccumulationBuffer renderPasses(const Scene& scene, const Camera& camera,
                                const RenderSettings& settings, uint32_t passes);

// The mesh and the camera pose moved by p -> scale * p + offset (computed in double, rounded once).
MeshData transformMesh(MeshData mesh, double scale, const glm::dvec3& offset);
CameraPose transformPose(const CameraPose& pose, double scale, const glm::dvec3& offset);

// A direction uniform on the unit sphere, from two uniform numbers of `rng` (z, then the azimuth).
glm::dvec3 uniformUnitVector(std::mt19937_64& rng);

// A uniform sky of `radiance` in every channel.
Environment uniformSky(float radiance);

// The pixels whose mean, counts or standard errors differ between the two buffers (all of them
// when their sizes differ): zero when two renders are bit for bit the same.
size_t differingPixels(const AccumulationBuffer& a, const AccumulationBuffer& b);

// Pixel luminance means: the pixels are independent estimates of their own values.
std::vector<double> pixelLuminances(const AccumulationBuffer& buffer);

// Mean over pixels of z^2, z = (a - b) / sqrt(se_a^2 + se_b^2) with the per-pass standard errors:
// about 1 when two renders with different seeds estimate the same image. Pixels with zero error
// in both must agree exactly (else infinity); they do not count in the mean.
double meanSquaredZ(const AccumulationBuffer& a, const AccumulationBuffer& b);

// Whether every pixel mean is finite.
bool allFinite(const AccumulationBuffer& buffer);

}  // namespace strata::test
