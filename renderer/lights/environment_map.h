#pragma once
// A latitude-longitude radiance map and what lighting a scene by it needs, computed once when the
// map is read: the importance distribution of its texels, its radiance integrated over the sphere
// and its largest component.
//
// The distribution is MIS-compensated (Karlik, Sik, Vevoda, Skrivan & Krivanek 2019): it weighs
// each texel by how far its luminance rises above the map's mean over the sphere, and texels at or
// below the mean not at all. Next-event estimation is always combined with the BSDF's own samples
// by MIS, and those samples already carry the even part of the sky well (a cosine-weighted sample
// under a constant sky is the integrand's own shape); light samples spent on it only take weight
// from them. So shadow rays go where the map is brighter than its surroundings, a sun say, and a
// map of one radiance is not sampled at all. The BSDF's samples cover every direction the light's
// skip, so the estimate stays unbiased. All of it lives in the map's own frame (environment_map_light.h), so
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
    // Over the texels, in proportion to max(0, luminance - the mean luminance over the sphere)
    // times sin(theta), the sphere's area element in the map's coordinates: the compensated
    // density above. Uniform, and not to be sampled, where sampled() is false.
    const PiecewiseConstant2D& distribution() const { return distribution_; }
    // Whether some texel rises above the mean, so that the distribution has anything to sample.
    bool sampled() const { return sampledIntegral_ > 0.0; }
    // The integral over the sphere of max(0, luminance - its mean): the part of the map that the
    // distribution samples.
    double sampledIntegral() const { return sampledIntegral_; }
    // The integral of the radiance over the sphere, per channel (4 pi times its mean).
    const glm::dvec3& sphereIntegral() const { return sphereIntegral_; }
    // The largest radiance component of any texel (the truncation bound's Le_max).
    float maxRadiance() const { return maxRadiance_; }

private:
    Image image_;
    std::string name_;
    glm::dvec3 sphereIntegral_;  // before the distribution, which is built from it
    PiecewiseConstant2D distribution_;
    double sampledIntegral_;
    float maxRadiance_;
};

}  // namespace strata
