#include "rt/render/camera.h"

#include <cmath>
#include <numbers>

namespace rt {

Camera Camera::from_view(const SceneView& view) {
    Camera c;
    c.eye_ = view.eye;
    c.forward_ = normalize(view.look - view.eye);
    // "Up" is +y. With z increasing into the screen, +x is to the right: the view is
    // left-handed, as the manual describes its internals.
    Vec3 world_up{0.0, 1.0, 0.0};
    if (length(cross(world_up, c.forward_)) < 1e-12) {
        world_up = {0.0, 0.0, 1.0};  // looking straight up or down: +z stands in for up
    }
    c.right_ = normalize(cross(world_up, c.forward_));
    c.up_ = cross(c.forward_, c.right_);
    c.screen_distance_ = view.screen_distance;
    const double to_radians = std::numbers::pi / 180.0;
    c.half_width_ = view.screen_distance * std::tan(0.5 * view.view_angle_x_degrees * to_radians);
    c.half_height_ = view.screen_distance * std::tan(0.5 * view.view_angle_y_degrees * to_radians);
    c.pixels_x_ = view.width;
    c.pixels_y_ = view.height;
    return c;
}

Ray Camera::primary_ray(double px, double py) const {
    const double sx = (2.0 * px / pixels_x_ - 1.0) * half_width_;
    const double sy = (1.0 - 2.0 * py / pixels_y_) * half_height_;
    const Vec3 on_screen = eye_ + forward_ * screen_distance_ + right_ * sx + up_ * sy;
    return {on_screen, normalize(on_screen - eye_)};
}

}  // namespace rt
