// Bins of directions: a cube map, 6 faces of k x k bins. A direction belongs to the face of its
// largest |component| and, on it, to the bin of its two other components divided by that one.
// A set of bins is stored as one k-bit row mask per face row (k <= 16).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "rt/core/bounds.h"
#include "rt/core/vec3.h"

namespace rt {

/// Where a direction falls: face (0..5: +x -x +y -y +z -z), row and column on the face.
struct DirectionBin {
    int face = 0;
    int row = 0;
    int column = 0;
};

/// The directions from a point of `start` to a point of `target`: the box of their differences,
/// widened for the rounding of the subtractions.
inline Box3 box_of_differences(const Box3& target, const Box3& start, double widen) {
    return Box3{target.lo - start.hi, target.hi - start.lo}.grown(widen);
}

class DirectionBins {
public:
    static constexpr int kMaxSide = 16;
    /// `side` bins along each edge of a face, 1..16.
    explicit DirectionBins(int side);

    int side() const { return side_; }
    /// Row masks per set of bins: 6 faces x side rows.
    int rows() const { return 6 * side_; }
    std::uint16_t full_row() const { return full_row_; }

    /// The bin of a finite nonzero direction (its length does not matter).
    DirectionBin bin_of(const Vec3& direction) const;
    /// The same, given 1 / direction per axis: a product instead of two divisions.
    DirectionBin bin_of(const Vec3& direction, const Vec3& inverse) const;
    bool contains(std::span<const std::uint16_t> set, const DirectionBin& bin) const {
        return (set[bin.face * side_ + bin.row] >> bin.column) & 1u;
    }

    /// Adds to `set` every bin holding a direction w / |w| for some w in `box` (w != 0), with a
    /// margin for rounding. Returns whether it added anything new.
    bool add_directions_of(const Box3& box, std::span<std::uint16_t> set) const;
    /// As above, but only the bins also in `only`.
    void add_directions_of(const Box3& box, std::span<std::uint16_t> set,
                           std::span<const std::uint16_t> only) const;
    /// Whether `set` already holds every bin add_directions_of(box) would add.
    bool holds_directions_of(const Box3& box, std::span<const std::uint16_t> set) const;
    /// Whether `set` holds every bin.
    bool holds_all(std::span<const std::uint16_t> set) const {
        return std::all_of(set.begin(), set.end(),
                           [&](std::uint16_t row) { return row == full_row_; });
    }

    /// Sets in `band` (rows() masks, cleared first) every bin holding a direction w with
    /// |dot(unit_normal, w / |w|)| <= cosine: the directions that see a plane (nearly) edge-on.
    /// Every bin for cosine >= 1.
    void band_of(const Vec3& unit_normal, double cosine, std::span<std::uint16_t> band) const;

private:
    static int major_axis(const Vec3& d) {
        const double ax = std::fabs(d.x);
        const double ay = std::fabs(d.y);
        const double az = std::fabs(d.z);
        return (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
    }
    /// The bin of `d`, whose largest |component| is along `axis`, given its reciprocal.
    DirectionBin bin_with(const Vec3& d, int axis, double inverse_major) const {
        if (!(inverse_major < Box3::kInfinity)) {
            return bin_of(d);  // a subnormal major component
        }
        // Rounded twice, so |u| may pass 1 by an ulp: cell_of() clamps it.
        const double u = d[(axis + 1) % 3] * inverse_major;
        const double v = d[(axis + 2) % 3] * inverse_major;
        return {2 * axis + (d[axis] < 0.0 ? 1 : 0), cell_of(v), cell_of(u)};
    }
    struct FaceRect {
        int row0, row1, column0, column1;  ///< inclusive; row0 > row1 when empty
    };
    FaceRect face_rect(const Box3& box, int face) const;
    int cell_of(double coordinate) const {
        // Truncation is floor here: the clamp first makes the value non-negative.
        const double scaled = std::clamp((coordinate + 1.0) * half_side_, 0.0, top_);
        return static_cast<int>(scaled);
    }
    std::uint16_t row_mask(const FaceRect& r) const;
    /// Calls visit(index of a row in a set, mask of the box's bins in it) for every row the
    /// box's directions reach, until visit returns false; returns whether none did.
    template <class Visit>
    bool for_each_row_of(const Box3& box, Visit&& visit) const;

    int side_;
    std::uint16_t full_row_;
    double half_side_;  ///< side / 2, and side - 1: the constants of cell_of()
    double top_;
    std::vector<Vec3> centres_;        ///< unit direction at the middle of each bin
    std::vector<double> radii_;        ///< largest angle from the centre to a corner of the bin
    std::vector<double> grazing_sin_;  ///< sin(radius + asin(kGrazingCosine)), capped at 1
};

}  // namespace rt
