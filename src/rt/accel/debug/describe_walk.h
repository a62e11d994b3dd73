// What the -dso switch prints: the voxels a walk visited for one ray, one line each. Implemented
// by the voxel methods (SEADS, the octree); the strike check asks for it.
#pragma once

#include <string>

#include "rt/core/ray.h"

namespace rt {

class DescribesWalk {
public:
    virtual ~DescribesWalk() = default;
    /// One line per voxel the ray's walk visits within the interval, in order: where the voxel
    /// is, the t at which the ray leaves it, and its polygon ids.
    virtual std::string describe_walk(const Ray& ray, Interval t) const = 0;
};

/// "(x, y, z)" with full precision, for ray reports.
std::string describe_vector(const Vec3& v);
/// "origin (..) direction (..) t (min, max)".
std::string describe_ray(const Ray& ray, Interval t);

}  // namespace rt
