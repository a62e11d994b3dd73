// The camera as the methods that keep something for eye rays alone see it (the z-buffer's item
// buffer, exit culling's covered pixels): which rays are eye rays, the pixel each one passes,
// and the pixels through which the eye can see a region of space. The tolerances are chosen
// together so that an eye ray's hit point always projects into the footprint of a region that
// holds it (eye_view.cpp argues why).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

#include "rt/core/bounds.h"
#include "rt/core/ray.h"
#include "rt/geometry/camera.h"

namespace rt {

/// The pixel of the view area an eye ray crosses the screen in.
struct ViewPixel {
    int x = 0;
    int y = 0;
};

/// An inclusive range of pixels of the view area; empty when x0 > x1.
struct PixelFootprint {
    int x0 = 1;
    int y0 = 1;
    int x1 = 0;
    int y1 = 0;
    bool empty() const { return x0 > x1 || y0 > y1; }
};

class EyeView {
public:
    static constexpr double kDepthTolerance = 1e-9;  ///< relative: an eye ray's origin's depth
    static constexpr double kOnScreen = 1e-6;  ///< pixels an origin may lie outside the view area

    /// No view: no ray is an eye ray.
    EyeView() = default;
    /// `scene_bounds`: the box of the scene's corners, for the rounding allowance.
    EyeView(const Camera& camera, const Box3& scene_bounds);

    /// False when the view has no area, is not a number or its axes are not orthonormal (as
    /// Camera::placed makes them): no ray is then an eye ray.
    bool usable() const { return usable_; }
    const Camera& camera() const { return camera_; }

    /// The pixel of a ray that starts on the screen and whose line passes through the eye (both
    /// within rounding), inside the view area, for t.min >= 0; none for any other ray.
    /// Inline: every eye ray asks it before it is culled or traced.
    std::optional<ViewPixel> pixel_of(const Ray& ray, Interval t) const {
        if (!usable_ || !(t.min >= 0.0)) {
            return std::nullopt;
        }
        const Camera& v = camera_;
        const Vec3 from_eye = ray.origin - v.eye;
        const double depth = dot(from_eye, v.forward);
        const double s = v.screen_distance;
        // Fails for an origin that is not finite, as the next test does for such a direction.
        if (!(std::fabs(depth - s) <= kDepthTolerance * s)) {
            return std::nullopt;
        }
        // |d x (O - E)| <= tolerance |d| |O - E|, on squares: no square root. The bound is
        // finite for any finite ray whose origin passed the depth test, short of a direction
        // near 1e150.
        const Vec3 off_line = cross(ray.direction, from_eye);
        const double bound =
            bound_factor_ * dot(ray.direction, ray.direction) * dot(from_eye, from_eye);
        if (!(dot(ray.direction, from_eye) > 0.0) || !(dot(off_line, off_line) <= bound) ||
            !std::isfinite(bound)) {
            return std::nullopt;
        }
        const double scale = s / depth;
        const double px =
            (dot(from_eye, v.right) * scale * inverse_half_width_ + 1.0) * 0.5 * v.width;
        const double py =
            (1.0 - dot(from_eye, v.up) * scale * inverse_half_height_) * 0.5 * v.height;
        if (!(px >= -kOnScreen && px <= v.width + kOnScreen && py >= -kOnScreen &&
              py <= v.height + kOnScreen)) {
            return std::nullopt;
        }
        return ViewPixel{std::clamp(static_cast<int>(px), 0, v.width - 1),
                         std::clamp(static_cast<int>(py), 0, v.height - 1)};
    }

    /// The pixels through which an eye ray can see a point of `points` or of their convex hull,
    /// widened by pixel_margin(). Every point must lie at depth near_depth() or beyond. The
    /// whole view for points whose projection is not a number (coordinates near the double
    /// range's end).
    PixelFootprint footprint_of(std::span<const Vec3> points) const;
    /// The same for the part of a box at depth near_depth() or beyond (empty when none is).
    PixelFootprint footprint_of(const Box3& box) const;

    /// Points nearer than this depth are never seen by an eye ray.
    double near_depth() const { return near_depth_; }
    /// How far off the eye an eye ray's line may pass, as an angle ...
    double angle_tolerance() const { return angle_tolerance_; }
    /// ... and as a distance at the screen's farthest corner.
    double eye_slack() const { return eye_slack_; }
    /// Footprints are widened by this many pixels.
    double pixel_margin() const { return pixel_margin_; }
    /// An absolute allowance for rounding at the scene's and the eye's scale (polygon_reach()).
    double rounding() const { return rounding_; }

private:
    Camera camera_;
    bool usable_ = false;
    double near_depth_ = 0.0;
    double angle_tolerance_ = 0.0;
    double eye_slack_ = 0.0;
    double pixel_margin_ = 0.0;
    double rounding_ = 0.0;
    double inverse_half_width_ = 0.0;
    double inverse_half_height_ = 0.0;
    double bound_factor_ = 0.0;  ///< angle_tolerance_ squared
};

}  // namespace rt
