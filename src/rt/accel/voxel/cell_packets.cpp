#include "rt/accel/voxel/cell_packets.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "rt/accel/parallel_parts.h"
#include "rt/accel/voxel/voxel_bounds.h"
#include "rt/core/error.h"
#include "rt/core/huge_pages.h"
#include "rt/geometry/ray_polygon.h"

#include <fmt/format.h>

namespace rt {

namespace {

// A cell's fan triangles, four lanes to a packet: the lanes a polygon of n corners takes.
std::uint64_t lanes_of(const Scene& scene, std::span<const std::uint32_t> ids) {
    std::uint64_t lanes = 0;
    for (const std::uint32_t id : ids) {
        const std::uint32_t corners = scene.polygons[id].corner_count;
        lanes += corners > 2 ? corners - 2 : 0;
    }
    return lanes;
}

// A cell's largest plane group (in_plane_group) goes first, its members in the cell's order, and
// the packets it fills alone are named in the cell's header (CellView). The packets a cell takes
// do not change. Only polygons whose corners are all finite floats join (the packets' scale then
// covers their corner 0), and only cells of 2 to 64 polygons are searched (a bit a polygon; the
// search is quadratic, on a hash of each normal's bits first).
constexpr std::size_t kMostGroupedPolygons = 64;

struct PlaneGroup {
    std::uint32_t leader = kNoPlaneGroup;
    std::uint32_t lanes = 0;    ///< the members' fan triangles
    std::uint64_t members = 0;  ///< bit k: the cell's k-th polygon
};

bool corners_are_floats(const Scene& scene, const Polygon& p) {
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        const Vec3 c = scene.corner_position(p, k);
        for (int a = 0; a < 3; ++a) {
            if (!(std::fabs(c[a]) <= std::numeric_limits<float>::max())) {
                return false;
            }
        }
    }
    return true;
}

PlaneGroup plane_group_of(const Scene& scene, std::span<const std::uint32_t> ids) {
    if (ids.size() < 2 || ids.size() > kMostGroupedPolygons) {
        return {};
    }
    std::array<std::uint64_t, kMostGroupedPolygons> hash{};
    std::uint64_t joining = 0;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const Polygon& p = scene.polygons[ids[i]];
        hash[i] = normal_bits_hash(p.normal);
        if (p.corner_count >= 3 && corners_are_floats(scene, p)) {
            joining |= std::uint64_t{1} << i;
        }
    }
    PlaneGroup best;
    for (std::uint64_t left = joining; left != 0; left &= left - 1) {
        const auto i = static_cast<std::size_t>(std::countr_zero(left));
        const Polygon& leader = scene.polygons[ids[i]];
        const Vec3 first = scene.corner_position(leader, 0);
        PlaneGroup group{ids[i], 0, 0};
        for (std::uint64_t rest = left; rest != 0; rest &= rest - 1) {
            const auto j = static_cast<std::size_t>(std::countr_zero(rest));
            if (hash[j] != hash[i]) {
                continue;
            }
            const Polygon& q = scene.polygons[ids[j]];
            if (same_normal_bits(q.normal, leader.normal) &&
                in_plane_group(leader.normal, first, scene.corner_position(q, 0))) {
                group.lanes += q.corner_count - 2;
                group.members |= std::uint64_t{1} << j;
            }
        }
        if (group.lanes > best.lanes) {
            best = group;
        }
    }
    return best.lanes >= 4 ? best : PlaneGroup{};
}

// Writes one cell's packets at `out`, one lane at a time, each packet completed on the stack and
// copied out whole; returns where the next cell's blocks go.
class PacketWriter {
public:
    explicit PacketWriter(unsigned char* out) : out_(out) {}

    /// `triangle`: the polygon's three corner indices if it is a triangle, else null.
    void add(const Vec3 (&corners)[3], std::uint32_t polygon, const std::uint32_t* triangle,
             double& scale) {
        if (lane_ == 4) {
            flush();
            std::fill(packet_.polygon, packet_.polygon + 4, kUnusedLane);
            for (int lane = 0; lane < 4; ++lane) {
                packet_.position.set(lane, nullptr);
            }
            std::fill(&packet_.corner[0][0][0], &packet_.corner[0][0][0] + 36,
                      std::numeric_limits<float>::quiet_NaN());
            lane_ = 0;
        }
        double size = 0.0;
        packet_.position.set(lane_, triangle);
        for (int v = 0; v < 3; ++v) {
            for (int a = 0; a < 3; ++a) {
                const auto f = static_cast<float>(corners[v][a]);
                packet_.corner[v][a][lane_] = f;
                size = std::max(size, std::fabs(static_cast<double>(f)));
            }
        }
        if (size < HUGE_VAL) {  // false for a NaN or an infinity
            scale = std::max(scale, size);
            packet_.polygon[lane_] = polygon;
        } else {
            packet_.polygon[lane_] = polygon | kAlwaysTestBit;
        }
        ++lane_;
        open_ = true;
    }

    /// Copies out the packet being filled, if any.
    void flush() {
        if (open_) {
            std::memcpy(out_, &packet_, sizeof(CellPacket));
            out_ += sizeof(CellPacket);
            open_ = false;
        }
    }

private:
    unsigned char* out_;
    CellPacket packet_{};
    int lane_ = 4;
    bool open_ = false;
};

// A polygon's fan triangles, one lane each, for the polygons in order whose bit in `chosen` is
// `wanted` (all of them past the 64th).
void write_fans(const Scene& scene, std::span<const std::uint32_t> polygons, std::uint64_t chosen,
                bool wanted, PacketWriter& writer, double& scale) {
    for (std::size_t n = 0; n < polygons.size(); ++n) {
        if (n < 64 && (((chosen >> n) & 1u) != 0) != wanted) {
            continue;
        }
        const std::uint32_t id = polygons[n];
        const Polygon& p = scene.polygons[id];
        const std::uint32_t* triangle =
            p.corner_count == 3 ? scene.corners.data() + p.first_corner : nullptr;
        Vec3 fan[3];
        fan[0] = scene.corner_position(p, 0);
        for (std::uint32_t k = 1; k + 1 < p.corner_count; ++k) {
            fan[1] = scene.corner_position(p, k);
            fan[2] = scene.corner_position(p, k + 1);
            writer.add(fan, id, triangle, scale);
        }
    }
}

// A cell's header: its bounds (voxel_bounds.h, in front of its ids), then the plane group's
// first polygon and packet count as bits (CellView). Returns where the packets go.
unsigned char* write_header(unsigned char* out, std::span<const std::uint32_t> ids,
                            const PlaneGroup& group) {
    const std::array<float, 6> box = bounds_before(ids);
    const auto group_packets = static_cast<std::uint32_t>(group.lanes / 4);  // filled alone
    float header[8] = {box[0], box[1], box[2], box[3], box[4], box[5], 0.0f, 0.0f};
    std::memcpy(&header[6], &group.leader, sizeof(std::uint32_t));
    std::memcpy(&header[7], &group_packets, sizeof(std::uint32_t));
    std::memcpy(out, header, sizeof(header));
    return out + sizeof(header);
}

}  // namespace

CellPackets::CellPackets(const Scene& scene, std::size_t cells, std::uint32_t bounds_slots,
                         const std::function<std::span<const std::uint32_t>(std::size_t)>& ids_of,
                         int threads)
    : with_bounds_(bounds_slots != 0) {
    // First each cell's size, so that the blocks are allocated once, at their size (growing them
    // cell by cell copied a million-triangle mesh's packets many times over), checked before,
    // and so that the cells can be filled on several threads, each into its own blocks.
    reserve_huge(first_, cells + 1);
    first_.resize(cells + 1);
    std::uint64_t blocks = 0;
    for (std::size_t c = 0; c < cells; ++c) {
        first_[c] = static_cast<std::uint32_t>(blocks);
        const std::span<const std::uint32_t> ids = ids_of(c);
        if (!ids.empty()) {
            blocks += (with_bounds_ ? kHeaderBlocks : 0) +
                      kPacketBlocks * ((lanes_of(scene, ids) + 3) / 4);
        }
        // Below 2^32 - 1, so that no count of blocks is all ones, which an octree node reads
        // as "interior" (octree.h).
        if (blocks >= std::numeric_limits<std::uint32_t>::max()) {
            throw Error(
                fmt::format("the voxels' triangle packets would take 2^32 - 1 blocks or more "
                            "of {} bytes: use fewer or larger voxels",
                            sizeof(Block)));
        }
    }
    first_[cells] = static_cast<std::uint32_t>(blocks);
    reserve_huge(blocks_, blocks);
    blocks_.resize(blocks);

    const int parts = build_threads_for(threads, scene.polygons.size());
    std::vector<double> scales(static_cast<std::size_t>(parts), 0.0);
    run_in_parts(cells, parts, [&](std::size_t begin, std::size_t end, int part) {
        double& scale = scales[static_cast<std::size_t>(part)];
        for (std::size_t c = begin; c < end; ++c) {
            const std::span<const std::uint32_t> ids = ids_of(c);
            if (ids.empty()) {
                continue;
            }
            auto* out = reinterpret_cast<unsigned char*>(blocks_.data() + first_[c]);
            // Only a cell with bounds has a header to name its plane group.
            const PlaneGroup group = with_bounds_ ? plane_group_of(scene, ids) : PlaneGroup{};
            if (with_bounds_) {
                static_assert(kHeaderBlocks * sizeof(Block) == sizeof(float[8]));
                out = write_header(out, ids, group);
            }
            PacketWriter writer(out);
            if (group.leader == kNoPlaneGroup) {
                write_fans(scene, ids, 0, false, writer, scale);
            } else {
                write_fans(scene, ids, group.members, true, writer, scale);
                write_fans(scene, ids, group.members, false, writer, scale);
            }
            writer.flush();
        }
    });
    // The largest over the parts: the same whatever the cut.
    scale_ = *std::max_element(scales.begin(), scales.end());
}

}  // namespace rt
