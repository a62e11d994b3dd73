// Builds small scenes by hand for tests: polygons from corner lists, sharing identical corners.
#pragma once

#include <cstdint>
#include <vector>

#include "rt/scene/scene.h"

namespace rt::test {

class SceneBuilder {
public:
    SceneBuilder();
    Scene& scene() { return scene_; }

    /// Adds a polygon; corners equal to an existing position share it. The normal is Newell's,
    /// turned to agree with `outward` (unless that is zero). Returns the polygon's id.
    std::uint32_t add_polygon(const std::vector<Vec3>& corners, const Vec3& outward = {},
                              std::uint32_t attribute = 0);

private:
    std::uint32_t position_of(const Vec3& p);
    Scene scene_;
};

/// Newell's normal of a loop (unit; zero for a degenerate loop).
Vec3 newell_normal(const std::vector<Vec3>& corners);

}  // namespace rt::test
