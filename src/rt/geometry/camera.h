// The pinhole camera (manual 2.2): eye, look point, +y up, a screen at screendist, view angles,
// and the view area in pixels. The renderer's eye rays and the z-buffer's projection both come
// from here, so they agree exactly. A scene's view makes one with SceneView::camera().
#pragma once

#include "rt/core/ray.h"
#include "rt/core/vec3.h"

namespace rt {

/// Where the camera stands and what it sees, as the .scn file's view gives it.
struct CameraPlacement {
    Vec3 eye;
    Vec3 look;
    double screen_distance = 1.0;
    double view_angle_x_degrees = 30.0;  ///< full angle subtended horizontally
    double view_angle_y_degrees = 30.0;  ///< full angle subtended vertically
    int width = 0;                       ///< view area in pixels
    int height = 0;
};

struct Camera {
    Vec3 eye;
    Vec3 forward;  ///< unit, from the eye towards the look point
    Vec3 right;    ///< unit; with `up` spans the screen
    Vec3 up;       ///< unit
    double screen_distance = 1.0;
    double half_width = 1.0;  ///< of the screen, in scene units
    double half_height = 1.0;
    int width = 1;  ///< view area in pixels
    int height = 1;

    /// Requires eye != look, positive screen distance and angles in (0, 180) degrees. "Up" is +y
    /// (+z when looking straight up or down); +x is to the right: the view is left-handed.
    static Camera placed(const CameraPlacement& placement);

    /// The eye ray through a point of the view area in pixels ((0, 0) the top-left corner of the
    /// top-left pixel, (width, height) the bottom-right corner of the last one). It starts on the
    /// screen (objects between the eye and the screen are not seen) and has a unit direction.
    Ray primary_ray(double px, double py) const;

    /// The point of the view area, in pixels, where the line from the eye through `p` meets the
    /// screen. `p` must be in front of the eye (depth(p) > 0).
    void project(const Vec3& p, double& px, double& py) const;
    /// Distance in front of the eye along `forward`.
    double depth(const Vec3& p) const { return dot(p - eye, forward); }
};

}  // namespace rt
