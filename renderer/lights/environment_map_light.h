#pragma once
// An HDR environment map in latitude-longitude form, seen by every ray that leaves the scene.
//
// Directions are in the map's frame, world +y up (the bundled scenes' camera up): the point
// (x, y) in [0,1)^2 of the image (x to the right, y down from the top row) is the direction of
// polar angle theta = pi y from +y and azimuth phi = 2 pi (x - 1/2) from -z toward +x, so the top
// row is straight up and the image's centre lies along -z; looking at it from inside, the image
// is not mirrored. Turning the map by alpha about +y (right-handed, counter-clockwise seen from
// above: the centre moves from -z toward -x for alpha > 0) rotates the whole frame. Radiance is
// constant over a texel.
//
// Next-event estimation samples the texels by the map's MIS-compensated piecewise-constant 2D
// distribution (environment_map.h: the luminance above the mean, times sin(theta), the sphere's
// area element in these coordinates), in the map's frame; the solid-angle density of a direction
// is then p(x, y) / (2 pi^2 sin(theta)), the Jacobian of (x, y) -> direction, and 0 where the map
// is not above its mean. A map of one radiance gives next-event estimation nothing to sample. The rotation turns the
// sampled directions and unturns the looked-up ones, so the light costs nothing to make.
#include <memory>

#include "lights/environment_map.h"
#include "lights/light.h"

namespace strata {

class EnvironmentMapLight final : public Light {
public:
    // `map` as readEnvironmentMap (environment.h) gives it; `sceneRadius`: the scene's bounding
    // sphere, through which the light's power flows.
    EnvironmentMapLight(std::shared_ptr<const EnvironmentMap> map, float rotationDegrees, float sceneRadius);

    std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const override;
    float pdf(const glm::vec3& point, const glm::vec3& direction, const LightHit& hit) const override;
    // The texel along `direction`, for any ray that left the scene.
    glm::vec3 emitted(const glm::vec3& direction, const LightHit& hit) const override;
    // pi r^2 times the radiance integrated over the sphere (= 4 pi times its mean), as pbrt-v4
    // counts the power an infinite light sends into the scene.
    glm::vec3 power() const override { return power_; }
    // pi r^2 times the luminance above the mean integrated over the sphere: what sample() draws.
    glm::vec3 sampledPower() const override { return sampledPower_; }

private:
    // The point of the image a world direction sees.
    glm::vec2 imagePoint(const glm::vec3& direction) const;
    const glm::vec3& texel(glm::ivec2 cell) const;

    std::shared_ptr<const EnvironmentMap> map_;
    float cosRotation_, sinRotation_;
    glm::vec3 power_;
    glm::vec3 sampledPower_;
};

}  // namespace strata
