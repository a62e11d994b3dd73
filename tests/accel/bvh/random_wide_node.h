// Wide nodes for the box tests' tests: seven random boxes and an empty eighth slot, as the builder
// leaves one, and the slab test in double to hold the float tests against.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/core/ray.h"

namespace rt::bvh::test {

inline float uniform(std::mt19937& rng, float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(rng);
}

/// Seven boxes in [-10, 10]^3 of sides from 0.01 to 8, child words 0 to 6, the last slot empty.
inline WideNode random_wide_node(std::mt19937& rng) {
    WideNode node{};
    for (int c = 0; c < 8; ++c) {
        for (int k = 0; k < 3; ++k) {
            const float size = std::pow(10.0f, uniform(rng, -2.0f, 0.9f));
            const float lo = uniform(rng, -10.0f, 10.0f - size);
            node.lo[k][c] = lo;
            node.hi[k][c] = lo + size;
        }
        node.child[c] = static_cast<std::uint32_t>(c);
    }
    for (int k = 0; k < 3; ++k) {
        node.lo[k][7] = std::numeric_limits<float>::infinity();
        node.hi[k][7] = -std::numeric_limits<float>::infinity();
    }
    node.child[7] = kNoChild;
    return node;
}

/// One of the eight corners of box `child`, drawn at random.
inline Vec3 random_corner(std::mt19937& rng, const WideNode& node, int child) {
    Vec3 corner;
    for (int k = 0; k < 3; ++k) {
        corner[k] = (rng() & 1U) != 0 ? node.lo[k][child] : node.hi[k][child];
    }
    return corner;
}

/// A point drawn uniformly in [-reach, reach]^3.
inline Vec3 random_point(std::mt19937& rng, float reach) {
    const float x = uniform(rng, -reach, reach);
    const float y = uniform(rng, -reach, reach);
    const float z = uniform(rng, -reach, reach);
    return {x, y, z};
}

struct Slab {
    double enter = -std::numeric_limits<double>::infinity();
    double exit = std::numeric_limits<double>::infinity();
};

/// Where the line origin + t * direction is inside box `child`, in double.
inline Slab exact_slab(const WideNode& node, int child, const Ray& ray) {
    Slab s;
    for (int k = 0; k < 3; ++k) {
        const double a = (node.lo[k][child] - ray.origin[k]) / ray.direction[k];
        const double b = (node.hi[k][child] - ray.origin[k]) / ray.direction[k];
        s.enter = std::max(s.enter, std::min(a, b));
        s.exit = std::min(s.exit, std::max(a, b));
    }
    return s;
}

}  // namespace rt::bvh::test
