#include "lights/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <glm/common.hpp>

#include "util/components.h"

namespace strata {
namespace {

// The largest float below 1: a number reused for the next step stays in [0,1).
constexpr float kBelowOne = 0x1.fffffep-1f;

float surfaceArea(const LightBounds& b) {
    const glm::vec3 d = b.upper - b.lower;
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

// The surface area orientation heuristic's cost of a child (Conty Estevez & Kulla 2018,
// equation 1): power x orientation measure x area, the area's share stretched by how thin the
// parent is along the split axis (pbrt-v4's K_r), which keeps clusters from growing long.
float splitCost(const LightBounds& child, const glm::vec3& parentExtent, int axis) {
    const float longest = std::max({parentExtent.x, parentExtent.y, parentExtent.z});
    const float stretch = parentExtent[axis] > 0.0f ? longest / parentExtent[axis] : 1.0f;
    return child.power * orientationMeasure(child) * stretch * surfaceArea(child);
}

// The SAOH's buckets per axis (as in pbrt-v4 and the paper's implementation, 12).
constexpr int kBuckets = 12;
// Below this depth a split follows the SAOH; from it on, the median by count, so that any tree
// of fewer than 2^32 lights is at most 64 levels deep and a light's trail fits in 64 bits.
constexpr int kHeuristicDepth = 32;

}  // namespace

LightTree::LightTree(const std::vector<std::unique_ptr<Light>>& lights) : places_(lights.size()), outside_({}) {
    std::vector<Item> items;
    std::vector<double> outsidePowers{0.0};  // entry 0: the tree
    outsideLight_.push_back(0);
    for (uint32_t i = 0; i < lights.size(); ++i) {
        const Light& light = *lights[i];
        const float power = meanComponent(light.sampledPower());
        const auto bounds = power > 0.0f ? light.bounds() : std::nullopt;
        if (bounds) {
            items.push_back({*bounds, i});
            items.back().bounds.power = power;
            outsidePowers[0] += power;
        } else {
            places_[i].entry = static_cast<int32_t>(outsidePowers.size());
            outsidePowers.push_back(power);
            outsideLight_.push_back(i);
        }
    }
    treeLights_ = items.size();
    if (!items.empty()) {
        nodes_.reserve(2 * items.size() - 1);
        build(items.begin(), items.end(), 0, 0);
    }
    outside_ = LightSampler(outsidePowers);
}

uint32_t LightTree::build(std::vector<Item>::iterator first, std::vector<Item>::iterator last, uint64_t trail,
                          int depth) {
    const auto index = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back({});
    if (last - first == 1) {
        nodes_[index] = {importanceBounds(first->bounds), first->light, true};
        places_[first->light].trail = trail;
        return index;
    }
    LightBounds bounds = first->bounds;
    glm::vec3 lowest = first->bounds.centre();
    glm::vec3 highest = lowest;
    for (auto it = first + 1; it != last; ++it) {
        bounds = unite(bounds, it->bounds);
        lowest = glm::min(lowest, it->bounds.centre());
        highest = glm::max(highest, it->bounds.centre());
    }
    const glm::vec3 centres = highest - lowest;
    auto bucketOf = [&](const Item& item, int axis) {
        const float t = (item.bounds.centre()[axis] - lowest[axis]) / centres[axis];
        return std::min(static_cast<int>(kBuckets * t), kBuckets - 1);
    };
    // The cheapest split between buckets by the SAOH, over the three axes.
    float bestCost = std::numeric_limits<float>::infinity();
    int bestAxis = -1;
    int bestSplit = 0;
    if (depth < kHeuristicDepth) {
        const glm::vec3 extent = bounds.upper - bounds.lower;
        for (int axis = 0; axis < 3; ++axis) {
            // A span that overflows (centres near the float range's ends) has no buckets: its
            // lights are split by count below, and bucketOf() only ever divides by a finite span.
            if (!(centres[axis] > 0.0f) || !std::isfinite(centres[axis])) continue;
            std::array<LightBounds, kBuckets> buckets{};
            std::array<bool, kBuckets> filled{};
            for (auto it = first; it != last; ++it) {
                const int b = bucketOf(*it, axis);
                buckets[b] = filled[b] ? unite(buckets[b], it->bounds) : it->bounds;
                filled[b] = true;
            }
            for (int split = 1; split < kBuckets; ++split) {
                std::optional<LightBounds> below, above;
                for (int b = 0; b < kBuckets; ++b) {
                    if (!filled[b]) continue;
                    auto& side = b < split ? below : above;
                    side = side ? unite(*side, buckets[b]) : buckets[b];
                }
                if (!below || !above) continue;
                const float cost = splitCost(*below, extent, axis) + splitCost(*above, extent, axis);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestSplit = split;
                }
            }
        }
    }
    std::vector<Item>::iterator middle;
    if (bestAxis >= 0) {
        middle = std::partition(first, last, [&](const Item& item) { return bucketOf(item, bestAxis) < bestSplit; });
    } else {
        // Every centre in one place, or deep: half of the lights by count along the longest axis.
        const int axis = centres.x >= centres.y && centres.x >= centres.z ? 0 : (centres.y >= centres.z ? 1 : 2);
        middle = first + (last - first) / 2;
        std::nth_element(first, middle, last, [axis](const Item& a, const Item& b) {
            return a.bounds.centre()[axis] < b.bounds.centre()[axis];
        });
    }
    build(first, middle, trail, depth + 1);
    const uint32_t second = build(middle, last, trail | (uint64_t{1} << depth), depth + 1);
    nodes_[index] = {importanceBounds(bounds), second, false};
    return index;
}

void LightTree::childProbabilities(const Node& node, uint32_t nodeIndex, const glm::vec3& point,
                                   const glm::vec3& normal, float& first, float& second) const {
    const ImportanceBounds& firstBounds = nodes_[nodeIndex + 1].bounds;
    const ImportanceBounds& secondBounds = nodes_[node.index].bounds;
    float a = importance(firstBounds, point, normal);
    float b = importance(secondBounds, point, normal);
    if (!(a + b > 0.0f)) {
        // Nothing under this node reaches the point, although the node's looser bounds did not
        // show it: the choice goes on by power, so that the probabilities still sum to one. The
        // light it ends at sends nothing, and its sample is dropped before any shadow ray.
        a = firstBounds.power;
        b = secondBounds.power;
    }
    const float sum = a + b;
    first = a / sum;
    second = b / sum;
}

LightChoice LightTree::choose(float u, const glm::vec3& point, const glm::vec3& normal) const {
    const LightChoice entry = outside_.choose(u);
    if (entry.light != 0) return {outsideLight_[entry.light], entry.probability};
    // The tree is entry 0, the interval [0, p) of u: u / p is uniform for the steps below.
    float v = std::min(u / entry.probability, kBelowOne);
    float probability = entry.probability;
    uint32_t nodeIndex = 0;
    while (!nodes_[nodeIndex].leaf) {
        const Node& node = nodes_[nodeIndex];
        float first, second;
        childProbabilities(node, nodeIndex, point, normal, first, second);
        if (v < first) {
            probability *= first;
            v = std::min(v / first, kBelowOne);
            nodeIndex = nodeIndex + 1;
        } else {
            probability *= second;
            v = std::min((v - first) / second, kBelowOne);
            nodeIndex = node.index;
        }
    }
    return {nodes_[nodeIndex].index, probability};
}

float LightTree::probability(uint32_t light, const glm::vec3& point, const glm::vec3& normal) const {
    const Place& place = places_[light];
    if (place.entry >= 0) return outside_.probability(static_cast<uint32_t>(place.entry));
    float probability = outside_.probability(0);
    uint64_t trail = place.trail;
    uint32_t nodeIndex = 0;
    while (!nodes_[nodeIndex].leaf) {
        const Node& node = nodes_[nodeIndex];
        float first, second;
        childProbabilities(node, nodeIndex, point, normal, first, second);
        if (trail & 1) {
            probability *= second;
            nodeIndex = node.index;
        } else {
            probability *= first;
            nodeIndex = nodeIndex + 1;
        }
        trail >>= 1;
    }
    return probability;
}

}  // namespace strata
