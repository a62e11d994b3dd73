// Why an eye ray's hit point projects into the footprint of any region that holds it.
//
// An eye ray here is one whose origin O lies on the screen (depth within 1e-9 of the screen
// distance s) and whose direction d is within angle_tolerance_ of O - E (E the eye): the
// camera's rays are, to within rounding. With t > t.min >= 0, the hit point Y = O + t d has
// depth >= depth(O) > near_depth_, and the direction of Y - E lies between those of O - E and
// d, so Y is seen from the eye within angle_tolerance_ of O: on the screen, within
// pixel_margin_ pixels of O's own pixel position. So if Y lies in a region (a set of points, or
// a box), O's pixel is in the footprint of the region's part at depth >= near_depth_: the
// screen box of that part's projection (for a box crossing the near plane, the projection of
// its corners in front and of its edges' crossings), widened by pixel_margin_.
//
// pixel_of() finds O's pixel with products by the screen's reciprocal half sizes where
// Camera::project divides: the two differ by a few units in the last place of a pixel
// position, far inside the 2 kOnScreen and 1e-12 (width + height) pixels of the margin.
#include "rt/accel/hit_regions/eye_view.h"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

constexpr double kAngleTolerance = 1e-9;

bool orthonormal(const Vec3& a, const Vec3& b, const Vec3& c) {
    constexpr double kOff = 1e-9;
    const auto unit = [](const Vec3& v) { return std::fabs(dot(v, v) - 1.0) <= kOff; };
    return unit(a) && unit(b) && unit(c) && std::fabs(dot(a, b)) <= kOff &&
           std::fabs(dot(b, c)) <= kOff && std::fabs(dot(a, c)) <= kOff;
}

}  // namespace

EyeView::EyeView(const Camera& camera, const Box3& scene_bounds) : camera_(camera) {
    const Camera& v = camera_;
    const double s = v.screen_distance;
    usable_ = v.width > 0 && v.height > 0 && s > 0.0 && v.half_width > 0.0 && v.half_height > 0.0 &&
              std::isfinite(s * v.half_width * v.half_height) && is_finite(v.eye) &&
              orthonormal(v.forward, v.right, v.up);
    if (!usable_) {
        return;
    }
    near_depth_ = s * (1.0 - 1e-6);
    angle_tolerance_ = kAngleTolerance;
    const double wide =
        1.0 + (v.half_width * v.half_width + v.half_height * v.half_height) / (s * s);
    eye_slack_ = 1.01 * angle_tolerance_ * s * std::sqrt(wide);
    const double pixel = std::min(2.0 * v.half_width / v.width, 2.0 * v.half_height / v.height);
    pixel_margin_ =
        1.01 * angle_tolerance_ * s * wide / pixel + 2.0 * kOnScreen + 1e-12 * (v.width + v.height);
    const double farthest =
        length(max_components(scene_bounds.hi - v.eye, v.eye - scene_bounds.lo));
    const double magnitude = std::max(scene_bounds.magnitude(), Box3::around(v.eye).magnitude());
    rounding_ = 1e-12 * (farthest + s * std::sqrt(wide) + magnitude);
    inverse_half_width_ = 1.0 / v.half_width;
    inverse_half_height_ = 1.0 / v.half_height;
    bound_factor_ = angle_tolerance_ * angle_tolerance_;
}

PixelFootprint EyeView::footprint_of(std::span<const Vec3> points) const {
    if (!usable_) {
        return {};
    }
    double x_lo = Box3::kInfinity;
    double x_hi = -Box3::kInfinity;
    double y_lo = Box3::kInfinity;
    double y_hi = -Box3::kInfinity;
    const int width = camera_.width;
    const int height = camera_.height;
    for (const Vec3& p : points) {
        double px = 0.0;
        double py = 0.0;
        camera_.project(p, px, py);
        if (std::isnan(px) || std::isnan(py)) {
            return {0, 0, width - 1, height - 1};  // beyond the double range: anywhere
        }
        x_lo = std::min(x_lo, px);
        x_hi = std::max(x_hi, px);
        y_lo = std::min(y_lo, py);
        y_hi = std::max(y_hi, py);
    }
    // Widened by the margin, and by a relative part for the rounding of far-out projections.
    auto clamp_to = [&](double v, double sign, int size) {
        const double widened = v + sign * (pixel_margin_ + 1e-12 * std::fabs(v));
        return static_cast<int>(std::clamp(std::floor(widened), -1.0, static_cast<double>(size)));
    };
    PixelFootprint f{clamp_to(x_lo, -1.0, width), clamp_to(y_lo, -1.0, height),
                     clamp_to(x_hi, 1.0, width), clamp_to(y_hi, 1.0, height)};
    if (!(x_lo <= x_hi && y_lo <= y_hi) || f.x1 < 0 || f.y1 < 0 || f.x0 >= width ||
        f.y0 >= height) {
        return {};
    }
    f.x0 = std::max(f.x0, 0);
    f.y0 = std::max(f.y0, 0);
    f.x1 = std::min(f.x1, width - 1);
    f.y1 = std::min(f.y1, height - 1);
    return f;
}

PixelFootprint EyeView::footprint_of(const Box3& box) const {
    if (!usable_ || box.empty()) {
        return {};
    }
    // The corners in front of the near plane, and where the edges cross it.
    Vec3 points[8 + 12];
    int count = 0;
    for (int a = 0; a < 8; ++a) {
        const Vec3 pa = box.corner(a);
        const double da = camera_.depth(pa);
        if (da >= near_depth_) {
            points[count++] = pa;
        }
        for (int bit = 1; bit < 8; bit <<= 1) {
            const Vec3 pb = box.corner(a | bit);
            const double db = camera_.depth(pb);
            if ((a & bit) == 0 && (da >= near_depth_) != (db >= near_depth_)) {
                points[count++] = pa + (pb - pa) * ((near_depth_ - da) / (db - da));
            }
        }
    }
    if (count == 0) {
        return {};
    }
    return footprint_of(std::span<const Vec3>(points, static_cast<std::size_t>(count)));
}

}  // namespace rt
