// The pinhole camera's geometry as the z-buffer needs it: eye, frame, screen and pixel grid. The
// accel module cannot see render/camera.h, so this mirrors Camera::from_view() and
// Camera::primary_ray() (manual 2.2: eye, look point, +y up, screen at screendist, view angles);
// a render test checks that the two agree.
#pragma once

#include "rt/geometry/ray.h"
#include "rt/scene/scene.h"

namespace rt {

struct PinholeView {
    Vec3 eye;
    Vec3 forward;  ///< unit, from the eye towards the look point
    Vec3 right;    ///< unit; with `up` spans the screen
    Vec3 up;       ///< unit
    double screen_distance = 1.0;
    double half_width = 1.0;  ///< of the screen, in scene units
    double half_height = 1.0;
    int width = 1;  ///< view area in pixels
    int height = 1;

    /// The frame of Camera::from_view(view).
    static PinholeView from_view(const SceneView& view);

    /// As Camera::primary_ray(): the eye ray through a point of the view area in pixels ((0, 0)
    /// the top-left corner of the top-left pixel), starting on the screen, unit direction.
    Ray primary_ray(double px, double py) const;

    /// The point of the view area, in pixels, where the line from the eye through `p` meets the
    /// screen. `p` must be in front of the eye (depth(p) > 0).
    void project(const Vec3& p, double& px, double& py) const;
    /// Distance in front of the eye along `forward`.
    double depth(const Vec3& p) const { return dot(p - eye, forward); }
};

}  // namespace rt
