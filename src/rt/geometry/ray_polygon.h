// Exact, watertight ray-polygon intersection for planar polygons of any number of corners,
// convex or concave (manual 1.3: "the most time-consuming process ... is finding intersections").
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "rt/geometry/ray.h"
#include "rt/scene/scene.h"

namespace rt {

/// A ray prepared once for many polygon tests: the shear that takes it to the +z axis
/// (Woop, Benthin and Wald, "Watertight ray/triangle intersection", JCGT 2013).
class RaySpace {
public:
    explicit RaySpace(const Ray& ray);
    const Ray& ray() const { return ray_; }
    /// The corner's 2D position seen along the ray; bit-identical for a corner shared by
    /// neighbouring polygons, which is what makes the test watertight.
    void project(const Vec3& corner, double& x, double& y) const;
    bool valid() const { return valid_; }

private:
    Ray ray_;
    int kx_ = 0;
    int ky_ = 1;
    int kz_ = 2;
    double shear_x_ = 0.0;
    double shear_y_ = 0.0;
    bool valid_ = false;
};

/// Whether the ray passes through the polygon whose corners are given in loop order, by the
/// winding number of the ray in its own 2D space. Ties (the ray exactly on an edge or a corner)
/// are decided by one consistent infinitesimal displacement of the ray, so a ray through a shared
/// edge or vertex of a closed mesh goes through exactly one of the polygons sharing it.
bool ray_passes_through(const RaySpace& space, std::span<const Vec3> corners);

/// The t at which the ray meets the plane through `point` with normal `normal`, if the ray is
/// not parallel to it.
std::optional<double> plane_hit(const Ray& ray, const Vec3& point, const Vec3& normal);

/// The t of the ray's hit on scene polygon `polygon`, strictly inside the interval.
std::optional<double> intersect_polygon(const RaySpace& space, const Scene& scene,
                                        std::uint32_t polygon, Interval t);

}  // namespace rt
