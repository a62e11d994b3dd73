// The item buffer behind z-buffer first hits: for every pixel of the view area, the polygons an
// eye ray through that pixel can hit, nearest first. Conservative by construction
// (item_buffer.cpp argues why), so testing a pixel's list gives brute force's answer exactly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rt/accel/hit_regions/eye_view.h"
#include "rt/geometry/camera.h"
#include "rt/scene/scene.h"

namespace rt {

struct ZBufferSettings {
    /// The most the item buffer may take; over it, the z-buffer stays off (every ray goes to the
    /// fallback) and says why. Checked before anything big is allocated.
    std::size_t max_bytes = std::size_t{256} << 20;
};

/// Where an eye ray crosses the screen.
struct EyeRayPixel {
    int x = 0;
    int y = 0;
    double from_eye = 0.0;  ///< distance from the eye to the ray's origin
};

class ItemBuffer {
public:
    ItemBuffer(const Scene& scene, const Camera& view, const ZBufferSettings& settings);

    /// False when the buffer would not fit (see inactive_reason()).
    bool active() const { return active_; }
    const std::string& inactive_reason() const { return inactive_reason_; }

    /// The pixel of a ray that starts on the screen and whose line passes through the eye (both
    /// within rounding), inside the view area, for t.min >= 0; none for any other ray.
    std::optional<EyeRayPixel> pixel_of(const Ray& ray, Interval t) const;

    /// The candidates of a pixel, as ranks: nearest first.
    std::span<const std::uint32_t> candidates(int x, int y) const {
        const std::size_t pixel = static_cast<std::size_t>(y) * view().width + x;
        return {entries_.data() + offsets_[pixel], entries_.data() + offsets_[pixel + 1]};
    }
    std::uint32_t polygon(std::uint32_t rank) const { return ranked_polygons_[rank]; }
    /// A lower bound on the distance from the eye of any hit point the polygon can report.
    double nearest(std::uint32_t rank) const { return ranked_nearest_[rank]; }

    std::size_t entries() const { return entries_.size(); }
    std::size_t polygons_in_view() const { return ranked_polygons_.size(); }
    std::size_t longest_list() const;
    double pixel_margin() const { return eye_.pixel_margin(); }
    std::size_t memory_bytes() const;

private:
    const Camera& view() const { return eye_.camera(); }
    PixelFootprint footprint(const Scene& scene, std::uint32_t id, double& nearest) const;
    bool fits(std::size_t polygons, std::uint64_t entries);
    void fill(const std::vector<PixelFootprint>& footprints);

    EyeView eye_;
    std::size_t max_bytes_ = 0;
    bool active_ = true;
    std::string inactive_reason_;
    std::vector<std::uint32_t> ranked_polygons_;  ///< polygons in view, nearest first
    std::vector<double> ranked_nearest_;
    std::vector<std::uint32_t> offsets_;  ///< per pixel, row by row, into entries_; one more
    std::vector<std::uint32_t> entries_;  ///< ranks
};

}  // namespace rt
