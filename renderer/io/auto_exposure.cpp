#include "io/auto_exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "util/luminance.h"

namespace strata {

namespace {

struct Block {
    double luminance;  // the mean of its pixels
    int pixels;
};

// The image's blocks above black, in no particular order.
std::vector<Block> litBlocks(const Image& image) {
    std::vector<Block> blocks;
    for (int y0 = 0; y0 < image.height; y0 += kExposureBlock) {
        for (int x0 = 0; x0 < image.width; x0 += kExposureBlock) {
            double sum = 0.0;
            int pixels = 0;
            for (int y = y0; y < std::min(y0 + kExposureBlock, image.height); ++y) {
                for (int x = x0; x < std::min(x0 + kExposureBlock, image.width); ++x) {
                    sum += luminance(glm::dvec3(image.pixels[static_cast<size_t>(y) * image.width + x]));
                    ++pixels;
                }
            }
            const double mean = sum / pixels;
            if (mean > 0.0 && std::isfinite(mean)) blocks.push_back({mean, pixels});
        }
    }
    return blocks;
}

// The luminance above which lie `share` of the blocks' pixels (of the brightest block that
// holds part of that share). Reorders `blocks`.
double luminanceOfBrightest(std::vector<Block>& blocks, double share, double pixels) {
    std::sort(blocks.begin(), blocks.end(), [](const Block& a, const Block& b) { return a.luminance > b.luminance; });
    double counted = 0.0;
    for (const Block& block : blocks) {
        counted += block.pixels;
        if (counted >= share * pixels) return block.luminance;
    }
    return blocks.back().luminance;
}

}  // namespace

float autoExposure(const Image& image) {
    std::vector<Block> blocks = litBlocks(image);
    if (blocks.empty()) return 0.0f;
    double logSum = 0.0;
    double pixels = 0.0;
    for (const Block& block : blocks) {
        logSum += block.pixels * std::log2(block.luminance);
        pixels += block.pixels;
    }
    const double keyed = std::log2(kExposureKey) - logSum / pixels;
    const double highlights = std::log2(kHighlightLimit / luminanceOfBrightest(blocks, kHighlightShare, pixels));
    return std::clamp(static_cast<float>(std::min(keyed, highlights)), -kExposureLimit, kExposureLimit);
}

}  // namespace strata
