// Z-buffer first hits (manual part one: rt "compares octree, spatial enumeration and z-buffer
// performance"; the --zbuffer switch): eye rays, which the renderer sends through
// eye_ray_closest_hit, find their first polygon in a rasterised item buffer; every other ray, and
// every eye ray the buffer cannot answer, goes to the fallback.
// The answer is brute force's exactly: same t, same polygon, ties to the lowest id.
#pragma once

#include <memory>
#include <string>

#include "rt/accel/accelerator.h"
#include "rt/accel/zbuffer/item_buffer.h"
#include "rt/geometry/camera.h"

namespace rt {

/// What -p prints for the z-buffer.
struct ZBufferStatistics {
    bool active = false;
    std::string inactive_reason;  ///< why every ray goes to the fallback, when not active
    std::size_t polygons_in_view = 0;
    std::size_t entries = 0;       ///< (pixel, polygon) pairs
    std::size_t longest_list = 0;  ///< most candidates in one pixel
    std::size_t memory_bytes = 0;
    double build_seconds = 0.0;
};

/// The lines -p prints, without trailing newlines.
std::vector<std::string> describe(const ZBufferStatistics& statistics);

class ZBufferFirstHits : public Accelerator {
public:
    /// The scene and the fallback must outlive this.
    ZBufferFirstHits(const Scene& scene, const Camera& view, const Accelerator& fallback,
                     const ZBufferSettings& settings = {});

    std::string_view name() const override { return name_; }
    /// Every ray but the eye rays: the fallback's answer.
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override {
        return fallback_.closest_hit(ray, t, counters);
    }
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override {
        return fallback_.occluded(ray, t, counters);
    }
    /// Answered from the pixel's candidates. The buffer vouches only for rays of its own view
    /// (origin on the screen, line through the eye, within rounding, and t.min >= 0): any other
    /// ray sent here, and every ray while the buffer is off, goes to the fallback.
    std::optional<Hit> eye_ray_closest_hit(const Ray& ray, Interval t,
                                           TraceCounters& counters) const override;
    /// Every lane as eye_ray_closest_hit; while the buffer is off, the whole packet goes to the
    /// fallback as one, for its packet walk.
    void eye_ray_closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                    TraceCounters& counters) const override {
        if (!buffer_.active()) {
            fallback_.eye_ray_closest_hit_packet(packet, hits, counters);
            return;
        }
        for (int lane = 0; lane < kPacketSize; ++lane) {
            if ((packet.active >> lane) & 1u) {
                hits[lane] = eye_ray_closest_hit(packet.rays[lane], packet.t[lane], counters);
            }
        }
    }
    /// Packets of other rays go to the fallback whole, for its packet walk.
    void closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                            TraceCounters& counters) const override {
        fallback_.closest_hit_packet(packet, hits, counters);
    }
    std::uint32_t occluded_packet(const RayPacket& packet, TraceCounters& counters) const override {
        return fallback_.occluded_packet(packet, counters);
    }
    bool walks_packets() const override { return fallback_.walks_packets(); }
    /// The item buffer plus the fallback.
    std::size_t memory_bytes() const override;

    ZBufferStatistics statistics() const;

private:
    const Scene& scene_;
    const Accelerator& fallback_;
    double build_seconds_ = 0.0;  ///< set while buffer_ is built, so declared before it
    ItemBuffer buffer_;
    std::string name_;
};

/// The form the lead wires to --zbuffer: make_zbuffer_first_hits(scene,
/// scene.view.camera(), *accelerator).
std::unique_ptr<ZBufferFirstHits> make_zbuffer_first_hits(const Scene& scene, const Camera& view,
                                                          const Accelerator& fallback,
                                                          const ZBufferSettings& settings = {});

}  // namespace rt
