#pragma once
// Which light next-event estimation samples at a receiving point, by a bounding volume hierarchy
// over the lights with extent (Conty Estevez & Kulla 2018, "Importance Sampling of Many Lights
// with Adaptive Tree Splitting"; pbrt-v4's BVHLightSampler is the same idea). From the root, each
// step goes to one of two children with probability proportional to its importance at the point
// (light_bounds.h): nearer, brighter clusters facing the point get more of the shadow rays, and a
// cluster that provably sends nothing there gets none (unless nothing under its parent does). The
// probability of a light is the product of the steps to its leaf, found again from the root along
// the light's bit trail, so that probability() gives exactly what choose() gave.
//
// The lights without bounds stay outside the tree: lights at infinity and delta lights (point,
// directional). The tree as a whole and each of them are chosen first by sampled power, as the
// power sampler (light_sampler.h) chooses among all lights. Their share is then what it was under
// the power sampler, so a sky or sun keeps its shadow rays however many emitters there are, and a
// uniform sky, of sampled power 0 (MIS-compensated), is never chosen; only the choice within the
// tree depends on the point. (pbrt-v4 gives lights at infinity a share by count instead; with the
// power split a dim sky beside a bright room does not take half of the samples.)
#include <cstdint>
#include <memory>
#include <vector>
#include <glm/vec3.hpp>

#include "lights/light.h"
#include "lights/light_bounds.h"
#include "lights/light_sampler.h"

namespace strata {

class LightTree {
public:
    // Over `lights` (a scene's, by index), each weighted by its mean sampled power; lights of
    // power 0 are never chosen.
    explicit LightTree(const std::vector<std::unique_ptr<Light>>& lights);

    // A light for `point`, `normal` the receiving surface's (facing the side light is sampled
    // from) or zero for a surface that transmits. `u` uniform in [0,1). Not to be called when
    // no light has sampled power (SceneLights::sampler() is empty then too).
    LightChoice choose(float u, const glm::vec3& point, const glm::vec3& normal) const;
    // The probability with which choose() at `point` and `normal` gives `light`.
    float probability(uint32_t light, const glm::vec3& point, const glm::vec3& normal) const;

    // The lights in the tree.
    size_t treeLights() const { return treeLights_; }

private:
    struct Node {
        ImportanceBounds bounds;
        uint32_t index;  // a leaf's light, else the second child (the first follows the node)
        bool leaf;
    };
    // Where a light is: in the tree along `trail` (bit k: the second child at depth k), or the
    // power sampler's entry `entry` (the tree itself is entry 0).
    struct Place {
        uint64_t trail = 0;
        int32_t entry = -1;  // -1: in the tree
    };
    struct Item {
        LightBounds bounds;
        uint32_t light;
    };
    // Builds the subtree over `items`, reached along `trail` at `depth`; returns its node index.
    uint32_t build(std::vector<Item>::iterator first, std::vector<Item>::iterator last, uint64_t trail, int depth);
    // The probability of going to the first child of `node` at the point, and of the second.
    void childProbabilities(const Node& node, uint32_t nodeIndex, const glm::vec3& point,
                            const glm::vec3& normal, float& first, float& second) const;

    std::vector<Node> nodes_;           // depth first, the root first
    std::vector<Place> places_;         // per light
    std::vector<uint32_t> outsideLight_;  // per power-sampler entry but the tree's: its light
    LightSampler outside_;              // the tree (entry 0) and the lights outside it, by power
    size_t treeLights_ = 0;
};

}  // namespace strata
