#pragma once
// Reference images for error measurements:
//   - analytic scenes need none: a closed furnace has the exact radiance of notes section 5.1;
//   - other scenes use a high-spp render stored as EXR and named by a key that hashes everything
//     the image depends on (the scene's files, the camera, the size, the depth, next-event
//     estimation), so that editing any of them makes a new key and a stale reference is never
//     picked up.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <glm/vec3.hpp>

#include "scene/camera.h"
#include "integrator/path_integrator.h"
#include "scene/scene_loader.h"
#include "film/image_metrics.h"
#include "io/image_io.h"

namespace strata {

// The exact radiance every camera ray sees when the scene is a furnace: a closed, consistently
// oriented mesh seen from inside, one material whose emission Le and albedo rho (< 1) are the same
// on every triangle, and no point light in use. Then L_K = Le (1 - rho^(K+1)) / (1 - rho) per
// channel (notes section 5.1). nullopt for any other scene.
std::optional<glm::vec3> furnaceRadiance(const Scene& scene, const CameraPose& camera,
                                         const PathIntegratorSettings& integrator);

// 64-bit FNV-1a over every file the scene was parsed from (each one's name and bytes: the scene
// file, those it names, the scene description, the camera file), then the camera pose, the image
// size, the depth, the next-event flag and the sky in use (its radiance, or its map's texels and
// rotation). The sampler is not part of it: every unbiased sampler converges to the same image.
uint64_t referenceKey(const LoadedScene& loaded, const Camera& camera,
                      const PathIntegratorSettings& integrator);

// DIR/NAME-dK-KEY.exr, NAME from the scene (its folder's name when the file is scene.EXT).
std::filesystem::path referencePath(const std::filesystem::path& dir, const LoadedScene& loaded,
                                    const Camera& camera, const PathIntegratorSettings& integrator);

// A short name for a scene in tables and file names: the scene file's stem, or its folder's name
// when the stem is the generic "scene".
std::string sceneName(const std::filesystem::path& scenePath);

// What a run's error is measured against: the exact radiance of an analytic scene, or an image.
struct Reference {
    std::optional<glm::vec3> constant;
    Image image;
    std::string kind;  // "analytic", "file", "cache" or "made"
    // The image's own expected error against the exact one: zero for an analytic reference and
    // (not known) for a file; for a render, estimated from its two independent halves.
    ImageError own;
};

// A reference render: the mean r of two halves of independent seeds and equal spp, and the first
// half h1. A render x measured against r has E[(x - r)^2] = Var x + Var r per pixel when their
// noise is independent: at high spp the reference's share is much of what is measured (against a
// 4224-spp reference a 528-spp render of a model under a uniform sky measured about twice its own
// error), and it makes every estimator look alike. h1 - h2 = 2 (h1 - r) and Var(h1 - h2) =
// 4 Var r, so (h1 - r)^2 estimates Var r without bias, and imageError(h1, r) the reference's own.
Reference renderedReference(Image mean, const Image& firstHalf, std::string kind);

// The error of `image` against `reference`, less the reference's own (Reference::own): an
// unbiased estimate of the image's error against the exact one (RMSE from the MSE left, >= 0).
ImageError measure(const Image& image, const Reference& reference);

}  // namespace strata
