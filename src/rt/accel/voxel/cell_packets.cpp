#include "rt/accel/voxel/cell_packets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "rt/accel/voxel/voxel_bounds.h"

namespace rt {

namespace {

// Appends one lane to a cell's packets, opening a packet when the last one is full.
class PacketWriter {
public:
    void add(const Vec3 (&corners)[3], std::uint32_t polygon, double& scale) {
        if (lane_ == 4) {
            CellPacket empty{};
            std::fill(empty.polygon, empty.polygon + 4, kUnusedLane);
            std::fill(&empty.corner[0][0][0], &empty.corner[0][0][0] + 36,
                      std::numeric_limits<float>::quiet_NaN());
            packets_.push_back(empty);
            lane_ = 0;
        }
        CellPacket& packet = packets_.back();
        double size = 0.0;
        for (int v = 0; v < 3; ++v) {
            for (int a = 0; a < 3; ++a) {
                const auto f = static_cast<float>(corners[v][a]);
                packet.corner[v][a][lane_] = f;
                size = std::max(size, std::fabs(static_cast<double>(f)));
            }
        }
        if (size < HUGE_VAL) {  // false for a NaN or an infinity
            scale = std::max(scale, size);
            packet.polygon[lane_] = polygon;
        } else {
            packet.polygon[lane_] = polygon | kAlwaysTestBit;
        }
        ++lane_;
    }

    const std::vector<CellPacket>& packets() const { return packets_; }
    void clear() {
        packets_.clear();
        lane_ = 4;
    }

private:
    std::vector<CellPacket> packets_;
    int lane_ = 4;
};

}  // namespace

CellPackets::CellPackets(const Scene& scene, std::size_t cells, std::uint32_t bounds_slots,
                         const std::function<std::span<const std::uint32_t>(std::size_t)>& ids_of)
    : with_bounds_(bounds_slots != 0) {
    first_.reserve(cells + 1);
    PacketWriter writer;
    for (std::size_t c = 0; c < cells; ++c) {
        first_.push_back(static_cast<std::uint32_t>(blocks_.size()));
        const std::span<const std::uint32_t> ids = ids_of(c);
        if (ids.empty()) {
            continue;
        }
        writer.clear();
        for (const std::uint32_t id : ids) {
            const Polygon& p = scene.polygons[id];
            Vec3 fan[3];
            fan[0] = scene.corner_position(p, 0);
            for (std::uint32_t k = 1; k + 1 < p.corner_count; ++k) {
                fan[1] = scene.corner_position(p, k);
                fan[2] = scene.corner_position(p, k + 1);
                writer.add(fan, id, scale_);
            }
        }
        if (with_bounds_) {
            const std::array<float, 6> box = bounds_before(ids);
            blocks_.push_back({{box[0], box[1], box[2], box[3]}});
            blocks_.push_back({{box[4], box[5], 0.0f, 0.0f}});
        }
        const auto* from = reinterpret_cast<const Block*>(writer.packets().data());
        blocks_.insert(blocks_.end(), from, from + kPacketBlocks * writer.packets().size());
    }
    first_.push_back(static_cast<std::uint32_t>(blocks_.size()));
}

}  // namespace rt
