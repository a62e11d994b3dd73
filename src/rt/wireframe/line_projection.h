// Where a line in the scene falls in the picture: through the renderer's own camera
// (geometry/camera.h), so that the wireframe lies exactly on the ray-traced picture. Lines are
// cut at the screen, the near plane (eye rays start on the screen, so nothing nearer is seen),
// and at the edges of the view area. (The film's window is the raster's business: a window then
// shows exactly the pixels of the whole view's picture.)
#pragma once

#include <optional>

#include "rt/core/vec3.h"
#include "rt/geometry/camera.h"

namespace rt {

/// A point of the view area in pixels: (0, 0) is the top-left corner of the top-left pixel,
/// pixel (x, y) covers [x, x + 1) x [y, y + 1), as Camera::primary_ray takes them.
struct PixelPoint {
    double x = 0.0;
    double y = 0.0;
};

struct PixelSegment {
    PixelPoint from;
    PixelPoint to;
};

class LineProjection {
public:
    explicit LineProjection(const Camera& camera);

    /// The point's place in the picture, or nothing when it lies nearer than the screen.
    std::optional<PixelPoint> point(const Vec3& p) const;
    /// The part of the segment the view area shows, or nothing.
    std::optional<PixelSegment> segment(const Vec3& a, const Vec3& b) const;

private:
    Camera camera_;
};

}  // namespace rt
