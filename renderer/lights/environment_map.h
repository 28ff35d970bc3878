#pragma once
// A latitude-longitude radiance map and what lighting a scene by it needs, computed once when the
// map is read: the importance distribution of its texels, its radiance integrated over the sphere
// and its largest component. All of it lives in the map's own frame (environment_map_light.h), so
// turning the map about +y rotates directions only, and relighting a scene with the same map at
// another angle, or again after another environment, rebuilds none of it.
#include <string>
#include <glm/vec3.hpp>

#include "io/image_io.h"
#include "sampling/piecewise_constant_2d.h"

namespace strata {

class EnvironmentMap {
public:
    // `image`: twice as wide as high, texels finite and >= 0 (readEnvironmentMap checks them);
    // `name`: the file it came from, for what the panel and the log say about it.
    EnvironmentMap(Image image, std::string name);

    const Image& image() const { return image_; }
    const std::string& name() const { return name_; }
    // Over the texels, in proportion to luminance times sin(theta), the sphere's area element in
    // the map's coordinates.
    const PiecewiseConstant2D& distribution() const { return distribution_; }
    // The integral of the radiance over the sphere, per channel (4 pi times its mean).
    const glm::dvec3& sphereIntegral() const { return sphereIntegral_; }
    // The largest radiance component of any texel (the truncation bound's Le_max).
    float maxRadiance() const { return maxRadiance_; }

private:
    Image image_;
    std::string name_;
    PiecewiseConstant2D distribution_;
    glm::dvec3 sphereIntegral_;
    float maxRadiance_;
};

}  // namespace strata
