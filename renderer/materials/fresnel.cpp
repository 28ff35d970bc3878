#include "materials/fresnel.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace strata {

glm::vec3 schlickFresnel(const glm::vec3& f0, float cosine) {
    const float m = std::clamp(1.0f - cosine, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (glm::vec3(1.0f) - f0) * (m2 * m2 * m);
}

float schlickFresnel(float f0, float cosine) { return schlickFresnel(glm::vec3(f0), cosine).x; }

float dielectricFresnel(float cosThetaI, float eta) {
    cosThetaI = std::clamp(cosThetaI, -1.0f, 1.0f);
    if (cosThetaI < 0.0f) {
        eta = 1.0f / eta;
        cosThetaI = -cosThetaI;
    }
    // Snell's law: sin(theta_t) = sin(theta_i) / eta.
    const float sin2ThetaT = (1.0f - cosThetaI * cosThetaI) / (eta * eta);
    if (sin2ThetaT >= 1.0f) return 1.0f;
    const float cosThetaT = std::sqrt(std::max(0.0f, 1.0f - sin2ThetaT));
    const float parallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
    const float perpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
    return 0.5f * (parallel * parallel + perpendicular * perpendicular);
}

glm::vec3 reflect(const glm::vec3& w, const glm::vec3& n) { return 2.0f * glm::dot(w, n) * n - w; }

std::optional<glm::vec3> refract(const glm::vec3& wi, const glm::vec3& n, float eta) {
    const float cosThetaI = glm::dot(n, wi);
    const float sin2ThetaT = std::max(0.0f, 1.0f - cosThetaI * cosThetaI) / (eta * eta);
    if (sin2ThetaT >= 1.0f) return std::nullopt;
    const float cosThetaT = std::sqrt(1.0f - sin2ThetaT);
    return glm::normalize(-wi / eta + (cosThetaI / eta - cosThetaT) * n);
}

}  // namespace strata
