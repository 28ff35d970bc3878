#pragma once
// The memory a scene's decoded textures may take together, its materials' textures and its
// environment map alike (`--texture-budget`). Each image is counted from its file's header
// (readTextureHeader, io/texture_image.h) before anything is allocated for its texels, so a
// scene that would exhaust a desktop's memory is refused at the image that would cross the
// budget, with its figures and the option that raises it, instead of being killed by the system
// part-way.
//
// What is counted is the texels as stored (textures/texture.h): a byte a channel for 8-bit
// images, four for floats. A decoder's working memory comes and goes with one image on top of it.
#include <cstdint>
#include <string>

#include "textures/texture.h"

namespace strata {

// 4 GiB: what a desktop of 16 GB keeps beside the geometry, the film and the system.
inline constexpr uint64_t kDefaultTextureBudget = uint64_t{4} << 30;

class TextureBudget {
public:
    // `usedBytes` are spent already (textures loaded before).
    explicit TextureBudget(uint64_t limitBytes = kDefaultTextureBudget, uint64_t usedBytes = 0)
        : limit_(limitBytes), used_(usedBytes) {}

    // Counts a texture of `size` against the budget, or throws strata::Error, before it is
    // allocated: "WHAT is 16384 x 16384, 4 channels of 8 bits (1.0 GiB); with it the scene's
    // textures would take 4.2 GiB, over the --texture-budget of 4.0 GiB".
    void reserve(const TextureSize& size, const std::string& what);

    uint64_t limit() const { return limit_; }
    uint64_t used() const { return used_; }

private:
    uint64_t limit_;
    uint64_t used_;
};

// "512 KiB", "1.0 GiB": a byte count for messages, in the largest binary unit it fills.
std::string describeBytes(uint64_t bytes);

}  // namespace strata
