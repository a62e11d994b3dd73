// Why add_directions_of() never leaves out a direction of the box. On face (axis a, sign s), a
// direction w with s * w_a = z > 0 has face coordinates u = w_b / z and v = w_c / z. Over the box
// part with z in [z0, z1] (z0 = max(the box's lowest s * w_a, 0)) and w_b in [b0, b1], u ranges
// within [b0 / z1 or b0 / z0, b1 / z0 or b1 / z1] by the signs of b0 and b1 (and to -inf or +inf
// when z0 == 0), because u is monotone in w_b and in z separately. That rectangle, widened for
// rounding and cut to [-1, 1], is marked. bin_of() computes u the same way, to within an ulp (two
// when it multiplies by the reciprocal of z), and maps u to a column with the same monotone
// arithmetic, so the direction's bin lies inside.
#include "rt/accel/exit_culling/direction_bins.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rt/accel/hit_regions/polygon_reach.h"

namespace rt {

namespace {

// Face coordinates (and angles) are widened by this much (absolute, plus a relative part).
constexpr double kMargin = 1e-9;
constexpr double kHalfPi = 1.5707963267948966;

struct Range {
    double lo, hi;
};

// The range of w_b / z over w_b in [b0, b1] and z in [z0, z1], 0 <= z0, 0 < z1, given the
// reciprocals of z0 (infinite for 0) and z1. Multiplying by a reciprocal rounds twice, well
// within the margin.
Range ratio_range(double b0, double b1, double inverse_z0, double inverse_z1) {
    constexpr double kInf = Box3::kInfinity;
    Range r{};
    r.lo = b0 >= 0.0 ? b0 * inverse_z1 : (inverse_z0 < kInf ? b0 * inverse_z0 : -kInf);
    r.hi = b1 <= 0.0 ? b1 * inverse_z1 : (inverse_z0 < kInf ? b1 * inverse_z0 : kInf);
    r.lo -= kMargin + kMargin * std::fabs(r.lo);
    r.hi += kMargin + kMargin * std::fabs(r.hi);
    return r;
}

}  // namespace

DirectionBins::DirectionBins(int side)
    : side_(side),
      full_row_(static_cast<std::uint16_t>((1u << side) - 1u)),
      half_side_(0.5 * side),
      top_(side - 1) {
    if (side < 1 || side > kMaxSide) {
        throw std::invalid_argument("direction bins per face side must be 1..16");
    }
    // Bin geometry for band_of(): a bin's directions all lie within `radius` of its centre,
    // since the cap around the centre through its farthest corner holds the whole bin.
    const double step = 2.0 / side_;
    for (int face = 0; face < 6; ++face) {
        for (int row = 0; row < side_; ++row) {
            for (int column = 0; column < side_; ++column) {
                auto direction = [&](double u, double v) {
                    Vec3 w;
                    w[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
                    w[(face / 2 + 1) % 3] = u;
                    w[(face / 2 + 2) % 3] = v;
                    return normalize(w);
                };
                const double u0 = -1.0 + column * step;
                const double v0 = -1.0 + row * step;
                const Vec3 centre = direction(u0 + 0.5 * step, v0 + 0.5 * step);
                double radius = 0.0;
                for (int corner = 0; corner < 4; ++corner) {
                    const int corner_column = corner & 1;
                    const int corner_row = corner >> 1;  // the corners (0,0) (1,0) (0,1) (1,1)
                    const Vec3 c = direction(u0 + corner_column * step, v0 + corner_row * step);
                    radius = std::max(radius, std::acos(std::clamp(dot(c, centre), -1.0, 1.0)));
                }
                centres_.push_back(centre);
                radii_.push_back(radius);
                grazing_sin_.push_back(
                    std::sin(std::min(radius + std::asin(kGrazingCosine) + kMargin, kHalfPi)));
            }
        }
    }
}

DirectionBin DirectionBins::bin_of(const Vec3& d) const {
    const int axis = major_axis(d);
    const double major = std::fabs(d[axis]);
    // |d_b| <= major, so u and v are in [-1, 1] exactly.
    const double u = d[(axis + 1) % 3] / major;
    const double v = d[(axis + 2) % 3] / major;
    return {2 * axis + (d[axis] < 0.0 ? 1 : 0), cell_of(v), cell_of(u)};
}

DirectionBin DirectionBins::bin_of(const Vec3& d, const Vec3& inverse) const {
    const int axis = major_axis(d);
    return bin_with(d, axis, std::fabs(inverse[axis]));
}

DirectionBins::FaceRect DirectionBins::face_rect(const Box3& box, int face) const {
    const int axis = face / 2;
    const bool negative = face % 2 == 1;
    const double z0 = std::max(negative ? -box.hi[axis] : box.lo[axis], 0.0);
    const double z1 = negative ? -box.lo[axis] : box.hi[axis];
    if (!(z1 > 0.0)) {
        return {1, 0, 1, 0};
    }
    const int b = (axis + 1) % 3;
    const int c = (axis + 2) % 3;
    const double inverse_z0 = z0 > 0.0 ? 1.0 / z0 : Box3::kInfinity;
    const double inverse_z1 = 1.0 / z1;
    const Range u = ratio_range(box.lo[b], box.hi[b], inverse_z0, inverse_z1);
    const Range v = ratio_range(box.lo[c], box.hi[c], inverse_z0, inverse_z1);
    if (u.lo > 1.0 || u.hi < -1.0 || v.lo > 1.0 || v.hi < -1.0) {
        return {1, 0, 1, 0};
    }
    return {cell_of(std::max(v.lo, -1.0)), cell_of(std::min(v.hi, 1.0)),
            cell_of(std::max(u.lo, -1.0)), cell_of(std::min(u.hi, 1.0))};
}

std::uint16_t DirectionBins::row_mask(const FaceRect& r) const {
    return static_cast<std::uint16_t>(((1u << (r.column1 + 1)) - 1u) & ~((1u << r.column0) - 1u));
}

template <class Visit>
bool DirectionBins::for_each_row_of(const Box3& box, Visit&& visit) const {
    for (int face = 0; face < 6; ++face) {
        const FaceRect r = face_rect(box, face);
        if (r.row0 > r.row1 || r.column0 > r.column1) {
            continue;
        }
        const std::uint16_t mask = row_mask(r);
        for (int row = r.row0; row <= r.row1; ++row) {
            if (!visit(static_cast<std::size_t>(face) * static_cast<std::size_t>(side_) +
                           static_cast<std::size_t>(row),
                       mask)) {
                return false;
            }
        }
    }
    return true;
}

bool DirectionBins::add_directions_of(const Box3& box, std::span<std::uint16_t> set) const {
    bool added = false;
    for_each_row_of(box, [&](std::size_t row, std::uint16_t mask) {
        std::uint16_t& bits = set[row];
        added = added || (bits | mask) != bits;
        bits |= mask;
        return true;
    });
    return added;
}

bool DirectionBins::holds_directions_of(const Box3& box, std::span<const std::uint16_t> set) const {
    return for_each_row_of(
        box, [&](std::size_t row, std::uint16_t mask) { return (set[row] & mask) == mask; });
}

void DirectionBins::add_directions_of(const Box3& box, std::span<std::uint16_t> set,
                                      std::span<const std::uint16_t> only) const {
    for_each_row_of(box, [&](std::size_t row, std::uint16_t mask) {
        set[row] |= mask & only[row];
        return true;
    });
}

void DirectionBins::band_of(const Vec3& unit_normal, double cosine,
                            std::span<std::uint16_t> band) const {
    std::fill(band.begin(), band.end(), std::uint16_t{0});
    const bool everything = cosine >= 1.0 || !(dot(unit_normal, unit_normal) > 0.5);
    // The band's half-width as an angle, and each bin's reach towards it: a bin misses the band
    // when its centre is farther from the plane than its radius plus that half-width.
    const bool usual = cosine == kGrazingCosine;
    const double half_width = everything ? 0.0 : std::asin(cosine);
    for (int bin = 0; bin < static_cast<int>(centres_.size()); ++bin) {
        const double limit = usual
                                 ? grazing_sin_[bin]
                                 : std::sin(std::min(radii_[bin] + half_width + kMargin, kHalfPi));
        if (everything || std::fabs(dot(unit_normal, centres_[bin])) <= limit * (1.0 + kMargin)) {
            band[bin / side_] |= static_cast<std::uint16_t>(1u << (bin % side_));
        }
    }
}

}  // namespace rt
