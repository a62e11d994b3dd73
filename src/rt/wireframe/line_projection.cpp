#include "rt/wireframe/line_projection.h"

#include <algorithm>
#include <utility>

namespace rt {

namespace {

// Liang-Barsky: narrows [t0, t1] to where p + t * d keeps within [low, high] along one axis.
bool clip_axis(double p, double d, double low, double high, double& t0, double& t1) {
    if (d == 0.0) {
        return p >= low && p <= high;
    }
    double enter = (low - p) / d;
    double leave = (high - p) / d;
    if (enter > leave) {
        std::swap(enter, leave);
    }
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
    return t0 <= t1;
}

}  // namespace

LineProjection::LineProjection(const Camera& camera) : camera_(camera) {}

namespace {

// Points on the screen itself are seen (eye rays start there), whatever the rounding of depth().
constexpr double kOnTheScreen = 1e-12;

}  // namespace

std::optional<PixelPoint> LineProjection::point(const Vec3& p) const {
    if (camera_.depth(p) < camera_.screen_distance * (1.0 - kOnTheScreen)) {
        return std::nullopt;
    }
    PixelPoint q;
    camera_.project(p, q.x, q.y);
    return q;
}

std::optional<PixelSegment> LineProjection::segment(const Vec3& a, const Vec3& b) const {
    // Cut at the near plane first: beyond it the projection is a straight line again.
    const double da = camera_.depth(a) - camera_.screen_distance;
    const double db = camera_.depth(b) - camera_.screen_distance;
    if (da < 0.0 && db < 0.0) {
        return std::nullopt;
    }
    Vec3 near_a = a;
    Vec3 near_b = b;
    if (da < 0.0) {
        near_a = a + (b - a) * (da / (da - db));
    } else if (db < 0.0) {
        near_b = b + (a - b) * (db / (db - da));
    }
    PixelSegment s;
    camera_.project(near_a, s.from.x, s.from.y);
    camera_.project(near_b, s.to.x, s.to.y);
    // Then at the view area's edges, in pixels.
    const double dx = s.to.x - s.from.x;
    const double dy = s.to.y - s.from.y;
    double t0 = 0.0;
    double t1 = 1.0;
    if (!clip_axis(s.from.x, dx, 0.0, camera_.width, t0, t1) ||
        !clip_axis(s.from.y, dy, 0.0, camera_.height, t0, t1)) {
        return std::nullopt;
    }
    const PixelPoint from = s.from;
    s.from = {from.x + t0 * dx, from.y + t0 * dy};
    s.to = {from.x + t1 * dx, from.y + t1 * dy};
    return s;
}

}  // namespace rt
