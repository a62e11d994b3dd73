// The item buffer behind z-buffer first hits: for every pixel of the view area, the polygons an
// eye ray through that pixel can hit, nearest first. Conservative by construction
// (item_buffer.cpp argues why), so testing a pixel's list gives brute force's answer exactly.
// Exit culling keeps one too, its lists per tile of pixels (ZBufferSettings::tile_side): a tile's
// list is the union of its pixels'.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rt/accel/accelerator.h"
#include "rt/accel/hit.h"
#include "rt/accel/hit_regions/eye_view.h"
#include "rt/geometry/camera.h"
#include "rt/geometry/ray_polygon.h"
#include "rt/scene/scene.h"

namespace rt {

struct ZBufferSettings {
    /// The most the item buffer may take; over it, the z-buffer stays off (every ray goes to the
    /// fallback) and says why. Checked before anything big is allocated.
    std::size_t max_bytes = std::size_t{256} << 20;
    /// Pixels along each side of the square tiles that share one list (1: a list per pixel).
    int tile_side = 1;
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

    /// The candidates of a pixel (those of its tile), as ranks: nearest first.
    std::span<const std::uint32_t> candidates(int x, int y) const {
        const std::size_t tile = static_cast<std::size_t>(y / tile_side_) * tiles_across_ +
                                 static_cast<std::size_t>(x / tile_side_);
        return {entries_.data() + offsets_[tile], entries_.data() + offsets_[tile + 1]};
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
    /// The tiles a footprint of pixels meets.
    PixelFootprint tiles_of(const PixelFootprint& f) const;
    bool fits(std::size_t polygons, std::uint64_t entries);
    void fill(const std::vector<PixelFootprint>& footprints);

    EyeView eye_;
    std::size_t max_bytes_ = 0;
    int tile_side_ = 1;
    std::size_t tiles_across_ = 0;
    std::size_t tiles_down_ = 0;
    bool active_ = true;
    std::string inactive_reason_;
    std::vector<std::uint32_t> ranked_polygons_;  ///< polygons in view, nearest first
    std::vector<double> ranked_nearest_;
    std::vector<std::uint32_t> offsets_;  ///< per tile, row by row, into entries_; one more
    std::vector<std::uint32_t> entries_;  ///< ranks
};

/// The nearest hit of an eye ray through `pixel` (from buffer.pixel_of), as brute force finds it,
/// from the exact tests of the pixel's candidates with `space` (the ray's, valid): nearest first,
/// stopping at a polygon whose reach lies beyond the best hit so far.
std::optional<Hit> closest_hit_in_buffer(const Scene& scene, const ItemBuffer& buffer,
                                         const RaySpace& space, Interval t,
                                         const EyeRayPixel& pixel, TraceCounters& counters);

}  // namespace rt
