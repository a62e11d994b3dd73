#include "rt/geometry/camera.h"

#include <cmath>
#include <numbers>

namespace rt {

Camera Camera::placed(const CameraPlacement& placement) {
    Camera v;
    v.eye = placement.eye;
    v.forward = normalize(placement.look - placement.eye);
    // +y is up, and straight up or down +z stands in for it; the view is left-handed (+x right
    // with z into the screen), as the manual describes the original's internals.
    Vec3 world_up{0.0, 1.0, 0.0};
    if (length(cross(world_up, v.forward)) < 1e-12) {
        world_up = {0.0, 0.0, 1.0};
    }
    v.right = normalize(cross(world_up, v.forward));
    v.up = cross(v.forward, v.right);
    v.screen_distance = placement.screen_distance;
    const double to_radians = std::numbers::pi / 180.0;
    v.half_width =
        placement.screen_distance * std::tan(0.5 * placement.view_angle_x_degrees * to_radians);
    v.half_height =
        placement.screen_distance * std::tan(0.5 * placement.view_angle_y_degrees * to_radians);
    v.width = placement.width;
    v.height = placement.height;
    return v;
}

Ray Camera::primary_ray(double px, double py) const {
    const double sx = (2.0 * px / width - 1.0) * half_width;
    const double sy = (1.0 - 2.0 * py / height) * half_height;
    const Vec3 on_screen = eye + forward * screen_distance + right * sx + up * sy;
    return {on_screen, normalize(on_screen - eye)};
}

void Camera::project(const Vec3& p, double& px, double& py) const {
    const Vec3 from_eye = p - eye;
    const double scale = screen_distance / dot(from_eye, forward);
    const double sx = dot(from_eye, right) * scale;
    const double sy = dot(from_eye, up) * scale;
    px = (sx / half_width + 1.0) * 0.5 * width;
    py = (1.0 - sy / half_height) * 0.5 * height;
}

}  // namespace rt
