// The pinhole camera of the .scn file (manual 2.2): eye, look point, +y up, a screen at
// screendist, view angles, and the view area in pixels.
#pragma once

#include "rt/geometry/ray.h"
#include "rt/scene/scene.h"

namespace rt {

class Camera {
public:
    /// Requires eye != look, positive screen distance and angles in (0, 180) degrees.
    static Camera from_view(const SceneView& view);

    /// The eye ray through a point of the view area given in pixels: (0, 0) is the top-left
    /// corner of the top-left pixel, (width, height) the bottom-right corner of the last one.
    /// It starts on the screen (objects between the eye and the screen are not seen) and has a
    /// unit direction.
    Ray primary_ray(double px, double py) const;

    const Vec3& right() const { return right_; }
    const Vec3& up() const { return up_; }
    const Vec3& forward() const { return forward_; }

private:
    Vec3 eye_;
    Vec3 forward_;
    Vec3 right_;
    Vec3 up_;
    double screen_distance_ = 1.0;
    double half_width_ = 1.0;  ///< on the screen, in scene units
    double half_height_ = 1.0;
    double pixels_x_ = 1.0;
    double pixels_y_ = 1.0;
};

}  // namespace rt
