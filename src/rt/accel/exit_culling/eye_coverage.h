// Exit culling for eye rays: the pixels of the view through which an eye ray can hit anything.
// Every hit point lies in the box of an occupied cell (occupied_cells.h), and an eye ray's hit
// point projects into the footprint of any box holding it (hit_regions/eye_view.cpp); so an eye
// ray through a pixel that no occupied box's footprint covers hits nothing. The test costs a
// projection and one bit, where the inclusion-cone table clips the ray to the world and finds
// its entry cell and direction bin: a ray from the eye starts outside every full cell, so it
// always took that long way, which cost more than culling saved.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "rt/accel/exit_culling/occupied_cells.h"
#include "rt/accel/hit_regions/eye_view.h"
#include "rt/geometry/camera.h"

namespace rt {

class EyeCoverage {
public:
    /// The most pixels a view may have for a coverage to be made (a bit each: 8 MiB).
    static constexpr std::size_t kMaxPixels = std::size_t{1} << 26;

    enum class Verdict : std::uint8_t {
        NotAnEyeRay,  ///< the coverage says nothing: ask the table
        MayHit,       ///< an eye ray through a covered pixel
        HitsNothing,  ///< an eye ray through a pixel nothing covers
    };

    /// No coverage: every ray is NotAnEyeRay.
    EyeCoverage() = default;
    /// The coverage of `cells` (made for the same scene) seen through `camera`; `scene_bounds`
    /// the box of the scene's corners.
    EyeCoverage(const Camera& camera, const Box3& scene_bounds, const OccupiedCells& cells);

    Verdict verdict(const Ray& ray, Interval t) const {
        ViewPixel pixel;
        return verdict(ray, t, pixel);
    }
    /// The same, with the eye ray's pixel in `pixel` (unset for NotAnEyeRay).
    Verdict verdict(const Ray& ray, Interval t, ViewPixel& pixel) const {
        const std::optional<ViewPixel> seen = eye_.pixel_of(ray, t);
        if (!seen) {
            return Verdict::NotAnEyeRay;
        }
        pixel = *seen;
        const std::size_t bit = static_cast<std::size_t>(pixel.y) * width_ + pixel.x;
        return ((bits_[bit / 64] >> (bit % 64)) & 1u) != 0 ? Verdict::MayHit : Verdict::HitsNothing;
    }
    /// The view, unusable when there is no coverage.
    const EyeView& view() const { return eye_; }

    /// False when there is no coverage (see inactive_reason(), empty when none was made).
    bool active() const { return eye_.usable(); }
    const std::string& inactive_reason() const { return inactive_reason_; }
    std::size_t pixels() const { return static_cast<std::size_t>(width_) * height_; }
    std::size_t covered_pixels() const;
    std::size_t memory_bytes() const { return bits_.capacity() * sizeof(std::uint64_t); }

private:
    /// Sets the bits of pixels x0..x1 of row y.
    void cover(int y, int x0, int x1);

    EyeView eye_;  ///< unusable while there is no coverage
    int width_ = 0;
    int height_ = 0;
    std::vector<std::uint64_t> bits_;  ///< per pixel, row after row
    std::string inactive_reason_;      ///< empty when active, or when none was asked for
};

}  // namespace rt
