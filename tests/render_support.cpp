#include "render_support.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/common.hpp>

namespace strata::test {

glm::dvec3 uniformUnitVector(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const double z = 2.0 * uniform(rng) - 1.0;
    const double phi = 2.0 * M_PI * uniform(rng);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

AccumulationBuffer renderPasses(const Scene& scene, const Camera& camera,
                                const RenderSettings& settings, uint32_t passes) {
    AccumulationBuffer buffer(camera.width(), camera.height());
    ProgressiveRenderer renderer(scene, camera, settings);
    for (uint32_t pass = 0; pass < passes; ++pass) renderer.renderPass(buffer, pass);
    return buffer;
}

MeshData transformMesh(MeshData mesh, double scale, const glm::dvec3& offset) {
    for (auto& p : mesh.positions) p = glm::vec3(glm::dvec3(p) * scale + offset);
    for (auto& light : mesh.pointLights) {
        light.position = glm::vec3(glm::dvec3(light.position) * scale + offset);
    }
    return mesh;
}

CameraPose transformPose(const CameraPose& pose, double scale, const glm::dvec3& offset) {
    CameraPose moved = pose;
    moved.position = glm::vec3(glm::dvec3(pose.position) * scale + offset);
    moved.lookAt = glm::vec3(glm::dvec3(pose.lookAt) * scale + offset);
    return moved;
}

Environment uniformSky(float radiance) {
    Environment sky;
    sky.kind = Environment::Kind::Uniform;
    sky.radiance = glm::vec3(radiance);
    return sky;
}

size_t differingPixels(const AccumulationBuffer& a, const AccumulationBuffer& b) {
    if (a.pixelCount() != b.pixelCount()) return std::max(a.pixelCount(), b.pixelCount());
    size_t differing = 0;
    for (size_t p = 0; p < a.pixelCount(); ++p) {
        if (a.mean(p) != b.mean(p) || a.sampleCount(p) != b.sampleCount(p) ||
            a.completedPasses(p) != b.completedPasses(p) ||
            a.passStandardError(p) != b.passStandardError(p) ||
            a.sampleStandardError(p) != b.sampleStandardError(p)) {
            ++differing;
        }
    }
    return differing;
}

std::vector<double> pixelLuminances(const AccumulationBuffer& buffer) {
    std::vector<double> values(buffer.pixelCount());
    for (size_t i = 0; i < values.size(); ++i) values[i] = luminance(buffer.mean(i));
    return values;
}

double meanSquaredZ(const AccumulationBuffer& a, const AccumulationBuffer& b) {
    double sum = 0.0;
    size_t counted = 0;
    for (size_t i = 0; i < a.pixelCount(); ++i) {
        const double seA = a.passStandardError(i);
        const double seB = b.passStandardError(i);
        const double variance = seA * seA + seB * seB;
        const double difference = luminance(a.mean(i)) - luminance(b.mean(i));
        if (variance == 0.0) {
            // Both pixels constant (e.g. looking at nothing): they must agree exactly.
            if (difference != 0.0) return std::numeric_limits<double>::infinity();
            continue;
        }
        sum += difference * difference / variance;
        ++counted;
    }
    return counted ? sum / static_cast<double>(counted) : 0.0;
}

bool allFinite(const AccumulationBuffer& buffer) {
    for (size_t i = 0; i < buffer.pixelCount(); ++i) {
        const glm::dvec3 m = buffer.mean(i);
        if (!std::isfinite(m.x) || !std::isfinite(m.y) || !std::isfinite(m.z)) return false;
    }
    return true;
}

}  // namespace strata::test
