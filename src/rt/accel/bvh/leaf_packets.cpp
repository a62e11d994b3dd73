#include "rt/accel/bvh/leaf_packets.h"

#include "rt/accel/lane_exact_hit.h"
#include "rt/core/prefetch.h"

namespace rt::bvh {

namespace {

void set_lane(TrianglePacket& packet, int lane, const Vec3 (&corners)[3], std::uint32_t polygon,
              const std::uint32_t* positions) {
    packet.position.set(lane, positions);
    for (int v = 0; v < 3; ++v) {
        for (int k = 0; k < 3; ++k) {
            packet.corner[v][k][lane] = static_cast<float>(corners[v][k]);
        }
    }
    packet.polygon[lane] = polygon;
}

void copy_lane(TrianglePacket& packet, int from, int to) {
    packet.position.copy_lane(from, to);
    for (int v = 0; v < 3; ++v) {
        for (int k = 0; k < 3; ++k) {
            packet.corner[v][k][to] = packet.corner[v][k][from];
        }
    }
    packet.polygon[to] = packet.polygon[from];
}

// A leaf's polygons lie anywhere in the scene's arrays, and each triangle is three dependent
// reads away (polygon record, corner list, positions). Asking for every record, then every corner
// list, then every corner, before reading any, lets the cache misses of the leaf overlap instead
// of queueing one behind the other.
void prefetch_leaf(const Scene& scene, std::span<const PolygonReference> refs) {
    for (const PolygonReference& ref : refs) {
        prefetch(&scene.polygons[ref.polygon]);
    }
    for (const PolygonReference& ref : refs) {
        prefetch(scene.corners.data() + scene.polygons[ref.polygon].first_corner);
    }
    for (const PolygonReference& ref : refs) {
        const Polygon& p = scene.polygons[ref.polygon];
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            prefetch(&scene.positions[scene.corners[p.first_corner + k]]);
        }
    }
}

}  // namespace

std::uint32_t leaf_packet_count(std::span<const PolygonReference> refs) {
    std::uint32_t triangles = 0;
    for (const PolygonReference& ref : refs) {
        triangles += ref.triangles;
    }
    return (triangles + 3) / 4;
}

std::uint32_t write_leaf_packets(const Scene& scene, std::span<const PolygonReference> refs,
                                 TrianglePacket* out) {
    prefetch_leaf(scene, refs);
    TrianglePacket* packet = out - 1;
    int lane = 4;  // the current packet is full: start a new one
    for (const PolygonReference& ref : refs) {
        const Polygon& p = scene.polygons[ref.polygon];
        for (std::uint32_t i = 1; i + 1 < p.corner_count; ++i) {
            if (lane == 4) {
                ++packet;
                lane = 0;
            }
            const Vec3 corners[3] = {scene.corner_position(p, 0), scene.corner_position(p, i),
                                     scene.corner_position(p, i + 1)};
            const std::uint32_t* triangle =
                p.corner_count == 3 ? scene.corners.data() + p.first_corner : nullptr;
            set_lane(*packet, lane++, corners, ref.polygon, triangle);
        }
    }
    for (; lane < 4; ++lane) {
        copy_lane(*packet, lane - 1, lane);
    }
    packet->polygon[3] |= kLastPacketBit;
    return static_cast<std::uint32_t>(packet - out + 1);
}

}  // namespace rt::bvh
