#pragma once
// What a light tree (light_tree.h) knows of a light or of a cluster of lights: a box holding
// their points, a cone holding their normals (axis, spread theta_o) around which each emits
// within theta_e of its normal, and their power; and from these a conservative estimate of how
// much they can send to a receiving point: the importance of Conty Estevez & Kulla 2018,
// "Importance Sampling of Many Lights with Adaptive Tree Splitting", section 4.
#include <glm/vec3.hpp>

namespace strata {

struct LightBounds {
    glm::vec3 lower{0.0f};
    glm::vec3 upper{0.0f};
    glm::vec3 axis{0.0f, 0.0f, 1.0f};  // unit; the normals lie within theta_o of it
    float power = 0.0f;                // the lights' summed mean sampled power (light.h)
    float cosSpread = 1.0f;            // cos theta_o
    float cosEmission = 0.0f;          // cos theta_e; 0: each emits into its front hemisphere

    glm::vec3 centre() const { return 0.5f * (lower + upper); }
};

// What importance() reads of a light's or cluster's bounds, in the form it reads them fastest: the
// box as its circumscribed sphere, the spread's sine with its cosine.
struct ImportanceBounds {
    glm::vec3 centre;
    float radius;
    glm::vec3 axis;
    float power;
    float cosSpread;
    float sinSpread;
    float cosEmission;
};
ImportanceBounds importanceBounds(const LightBounds& bounds);

// Bounds holding both (the cones' union is the smallest cone holding both cones).
LightBounds unite(const LightBounds& a, const LightBounds& b);

// An estimate of the irradiance the lights of `bounds` send to `point`, from the box's distance
// and the least angles, over all points of the box, between the direction to `point` and the
// normals' cone, and between that direction and `normal`. Zero only where no light of the box
// can send anything there: behind every normal by more than theta_e, or (for a non-zero `normal`,
// a reflecting surface's) wholly below the surface's tangent plane. A zero `normal` cuts
// nothing: light from both sides counts (a transmitting surface).
float importance(const ImportanceBounds& bounds, const glm::vec3& point, const glm::vec3& normal);

// The build's cost of a cluster's orientation: the solid angle its cone and emission spread over,
// weighted by cosine (Conty Estevez & Kulla 2018, equation 1's M_Omega).
float orientationMeasure(const LightBounds& bounds);

}  // namespace strata
