#include "rt/accel/debug/describe_walk.h"

#include <fmt/format.h>

namespace rt {

std::string describe_vector(const Vec3& v) {
    return fmt::format("({}, {}, {})", v.x, v.y, v.z);
}

std::string describe_ray(const Ray& ray, Interval t) {
    return fmt::format("origin {} direction {} t ({}, {})", describe_vector(ray.origin),
                       describe_vector(ray.direction), t.min, t.max);
}

}  // namespace rt
