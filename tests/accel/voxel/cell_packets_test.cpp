// Each voxel's packets: one lane per fan triangle of each polygon, in the cell's order, the
// voxel's bounds copied in front, and a four-lane float test that never rejects a polygon the
// exact test hits.
#include "rt/accel/voxel/cell_packets.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <vector>

#include "rt/accel/voxel/cell_pair_test.h"
#include "rt/accel/voxel/voxel_bounds.h"
#include "rt/geometry/ray_polygon.h"

#include <gtest/gtest.h>

#include "support/meshes/generated_meshes.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

// The polygon words of every used lane of a cell's packets.
std::multiset<std::uint32_t> lane_polygons(std::span<const CellPacket> packets) {
    std::multiset<std::uint32_t> ids;
    for (const CellPacket& packet : packets) {
        for (unsigned lanes = used_lanes(packet); lanes != 0; lanes &= lanes - 1) {
            ids.insert(packet.polygon[std::countr_zero(lanes)]);
        }
    }
    return ids;
}

TEST(CellPackets, OneLanePerFanTriangleAndBoundsInFront) {
    test::SceneBuilder b;
    b.add_polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});                         // 0: 1 lane
    b.add_polygon({{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}});              // 1: 2 lanes
    b.add_polygon({{0, 0, 2}, {2, 0, 2}, {3, 1, 2}, {1, 3, 2}, {-1, 1, 2}});  // 2: 3 lanes
    b.add_polygon({{1e39, 0, 0}, {1e39, 1, 0}, {1e39, 0, 1}});  // 3: beyond float: always
    const Scene scene = std::move(b.scene());
    // Cells as a structure with bounds lays them out: 6 bound slots, then the ids.
    const std::vector<std::vector<std::uint32_t>> ids = {{0, 1, 2, 3}, {}, {2}};
    std::vector<std::vector<std::uint32_t>> slots;
    for (std::size_t c = 0; c < ids.size(); ++c) {
        std::vector<std::uint32_t> cell;
        for (int k = 0; k < 6; ++k) {
            cell.push_back(std::bit_cast<std::uint32_t>(static_cast<float>(10 * c + k)));
        }
        cell.insert(cell.end(), ids[c].begin(), ids[c].end());
        slots.push_back(cell);
    }
    const CellPackets packets(scene, ids.size(), kVoxelBoundsSlots, [&](std::size_t c) {
        return ids[c].empty() ? std::span<const std::uint32_t>{}
                              : std::span<const std::uint32_t>(slots[c]).subspan(6);
    });

    const CellView first = packets.cell(0);
    ASSERT_EQ(first.packets.size(), 2u);  // 7 lanes
    EXPECT_EQ(lane_polygons(first.packets),
              (std::multiset<std::uint32_t>{0, 1, 1, 2, 2, 2, 3 | kAlwaysTestBit}));
    ASSERT_NE(first.bounds, nullptr);
    for (int k = 0; k < 6; ++k) {
        EXPECT_EQ(first.bounds[k], static_cast<float>(k));
    }
    EXPECT_TRUE(packets.cell(1).packets.empty());
    EXPECT_EQ(lane_polygons(packets.cell(2).packets), (std::multiset<std::uint32_t>{2, 2, 2}));
    EXPECT_EQ(packets.cell(2).bounds[0], 20.0f);
    // The scale covers the finite corners only.
    EXPECT_EQ(packets.scale(), 3.0);
}

// With bounds, a cell's largest plane group of at least four lanes goes first, in the cell's
// order, and the header names its first polygon and the packets it fills alone; the cell takes
// no more packets than without.
TEST(CellPackets, PlaneGroupGoesFirst) {
    test::SceneBuilder b;
    b.add_polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});  // 0: z = 0, 2 lanes
    b.add_polygon({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}});             // 1: z = 5, 1 lane
    b.add_polygon({{2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0}});  // 2: z = 0, 2 lanes
    b.add_polygon({{4, 0, 0}, {5, 0, 0}, {4, 1, 0}});             // 3: z = 0, 1 lane
    b.add_polygon({{0, 0, 7}, {1, 0, 7}, {0, 1, 7}});             // 4: z = 7, 1 lane
    const Scene scene = std::move(b.scene());
    const std::vector<std::uint32_t> ids = {1, 0, 4, 2, 3};
    std::vector<std::uint32_t> slots(6, 0u);
    slots.insert(slots.end(), ids.begin(), ids.end());
    const std::span<const std::uint32_t> cell_ids =
        std::span<const std::uint32_t>(slots).subspan(6);
    const CellPackets with_bounds(scene, 1, kVoxelBoundsSlots,
                                  [&](std::size_t) { return cell_ids; });
    const CellView cell = with_bounds.cell(0);
    EXPECT_EQ(cell.plane_polygon, 0u);
    ASSERT_EQ(cell.plane_packets, 1u);  // 5 lanes of z = 0: one packet alone
    ASSERT_EQ(cell.packets.size(), 2u);
    EXPECT_EQ(lane_polygons(cell.packets.first(1)), (std::multiset<std::uint32_t>{0, 0, 2, 2}));
    EXPECT_EQ(cell.packets[1].polygon[0], 3u);  // the group's last lane, then the rest in order
    EXPECT_EQ(cell.packets[1].polygon[1], 1u);
    EXPECT_EQ(cell.packets[1].polygon[2], 4u);
    // Without bounds there is no header to name it: the cell's order.
    const CellPackets plain(scene, 1, 0, [&](std::size_t) { return cell_ids; });
    EXPECT_EQ(plain.cell(0).plane_packets, 0u);
    EXPECT_EQ(plain.cell(0).packets[0].polygon[0], 1u);
}

// A triangle's lane carries its corners' position indices in the polygon's own loop order, so that
// its exact test (lane_exact_hit.h) sees the same polygon as Scene::polygon_view; a lane of a
// larger polygon, and an unused lane, say they are not triangles and leave the test to the scene.
TEST(CellPackets, TriangleLanesCarryTheirCornersInLoopOrder) {
    test::SceneBuilder b;
    b.add_polygon({{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}});  // 0: a quad, 2 lanes
    b.add_polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});             // 1: a triangle
    b.add_polygon({{1e39, 0, 0}, {1e39, 1, 0}, {1e39, 0, 1}});    // 2: always tested
    b.add_polygon({{0, 0, 3}, {1, 0, 3}, {0, 1, 3}});             // 3: a triangle
    Scene scene = std::move(b.scene());
    // Corners out of step with positions, as a shared-vertex model has them.
    std::swap(scene.corners[scene.polygons[1].first_corner],
              scene.corners[scene.polygons[1].first_corner + 2]);
    const std::vector<std::uint32_t> ids = {0, 1, 2, 3};
    const CellPackets packets(scene, 1, 0, [&](std::size_t) { return std::span(ids); });
    const std::span<const CellPacket> cell = packets.cell(0).packets;
    ASSERT_EQ(cell.size(), 2u);  // 5 lanes, then 3 unused
    int triangles = 0;
    for (const CellPacket& packet : cell) {
        for (int lane = 0; lane < 4; ++lane) {
            const std::uint32_t id = packet.polygon[lane] & ~kAlwaysTestBit;
            if (packet.polygon[lane] == kUnusedLane || scene.polygons[id].corner_count != 3) {
                EXPECT_FALSE(packet.position.is_triangle(lane)) << "lane " << lane;
                continue;
            }
            ++triangles;
            const PolygonView view = scene.polygon_view(id);
            for (std::uint32_t v = 0; v < 3; ++v) {
                EXPECT_EQ(packet.position.corner(static_cast<int>(v), lane), view.corner_ids[v])
                    << "polygon " << id;
            }
        }
    }
    EXPECT_EQ(triangles, 3);
}

// Triangles, quads and pentagons (regular, in random planes) of many sizes, some far off.
Scene random_polygons(std::mt19937& rng, int count) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    test::SceneBuilder b;
    for (int i = 0; i < count; ++i) {
        const Vec3 centre =
            Vec3{normal(rng), normal(rng), normal(rng)} * (i % 5 == 0 ? 100.0 : 1.0);
        const double size = std::pow(10.0, 1.0 - 7.0 * unit(rng));
        const Vec3 u = normalize(Vec3{normal(rng), normal(rng), normal(rng)});
        const Vec3 v = normalize(cross(u, Vec3{normal(rng), normal(rng), normal(rng)}));
        const int corners = 3 + i % 3;
        std::vector<Vec3> loop;
        for (int k = 0; k < corners; ++k) {
            const double angle = 2.0 * M_PI * k / corners;
            loop.push_back(centre + (u * std::cos(angle) + v * std::sin(angle)) * size);
        }
        b.add_polygon(loop);
    }
    return std::move(b.scene());
}

TEST(CellPackets, NeverRejectAPolygonTheExactTestHits) {
    std::mt19937 rng(31);
    const Scene scene = random_polygons(rng, 600);
    std::vector<std::uint32_t> all(scene.polygons.size());
    for (std::uint32_t id = 0; id < all.size(); ++id) {
        all[id] = id;
    }
    const CellPackets packets(scene, 1, 0, [&](std::size_t) { return std::span(all); });
    const std::span<const CellPacket> cell = packets.cell(0).packets;
    ASSERT_EQ(packets.cell(0).bounds, nullptr);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    int hits = 0;
    int rejected = 0;
    for (int i = 0; i < 3000; ++i) {
        // Aimed at a point of a polygon's first fan triangle, or just beside it.
        const Polygon& p = scene.polygons[rng() % scene.polygons.size()];
        const double a = unit(rng) * 1.1;
        const double b = unit(rng) * (1.1 - a);
        const Vec3 c0 = scene.corner_position(p, 0);
        const Vec3 target =
            c0 + (scene.corner_position(p, 1) - c0) * a + (scene.corner_position(p, 2) - c0) * b;
        Ray ray{{normal(rng), normal(rng), normal(rng)}, {}};
        ray.direction = target - ray.origin;
        // Set up as the voxel methods set it up: only the triangle values, which must be the
        // full set-up's bit for bit.
        const FloatRay float_ray(ray, packets.scale(), FloatRay::TrianglesOnly{});
        ASSERT_TRUE(float_ray.usable);
        const FloatRay full(ray, packets.scale());
        ASSERT_TRUE(full.kx == float_ray.kx && full.ky == float_ray.ky && full.kz == float_ray.kz);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(full.shear_x),
                  std::bit_cast<std::uint32_t>(float_ray.shear_x));
        ASSERT_EQ(std::bit_cast<std::uint32_t>(full.shear_y),
                  std::bit_cast<std::uint32_t>(float_ray.shear_y));
        ASSERT_EQ(full.edge_margin_linear, float_ray.edge_margin_linear);
        ASSERT_EQ(full.edge_margin_constant, float_ray.edge_margin_constant);
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(std::bit_cast<std::uint32_t>(full.origin[k]),
                      std::bit_cast<std::uint32_t>(float_ray.origin[k]));
        }
        std::set<std::uint32_t> kept;
        for (const CellPacket& packet : cell) {
            for (unsigned lanes = static_cast<unsigned>(cell_packet_candidates(packet, float_ray));
                 lanes != 0; lanes &= lanes - 1) {
                kept.insert(packet.polygon[std::countr_zero(lanes)]);
            }
        }
        for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
            const bool hit = intersect_polygon(ray, scene.polygon_view(id),
                                               Interval{-kBeyondAnyScene, kBeyondAnyScene})
                                 .has_value();
            if (hit) {
                ASSERT_TRUE(kept.contains(id)) << "case " << i << ", polygon " << id;
                ++hits;
            } else if (!kept.contains(id)) {
                ++rejected;
            }
        }
    }
    EXPECT_GT(hits, 3000) << "too few hits for the test to mean much";
    EXPECT_GT(rejected, 500000) << "the float test rejects almost nothing";
}

// A lane the float test cannot judge (its corners beyond the float range) is a candidate for
// every ray, in the four-wide test and in the pair test, whichever lane it lands in.
TEST(CellPackets, AlwaysLanesAreCandidatesForEveryRay) {
    test::SceneBuilder b;
    for (int k = 0; k < 8; ++k) {
        const double x = k % 3 == 1 ? 1e39 : static_cast<double>(k);
        b.add_polygon({{x, 0, 0}, {x, 1, 0}, {x, 0, 1}});  // 1, 4 and 7 beyond float
    }
    const Scene scene = std::move(b.scene());
    const std::vector<std::uint32_t> ids = {0, 1, 2, 3, 4, 5, 6, 7};
    const CellPackets packets(scene, 1, 0, [&](std::size_t) { return std::span(ids); });
    const std::span<const CellPacket> cell = packets.cell(0).packets;
    ASSERT_EQ(cell.size(), 2u);
    for (const CellPacket& packet : cell) {
        unsigned expected = 0;
        for (unsigned lane = 0; lane < 4; ++lane) {
            expected |= (packet.polygon[lane] & kAlwaysTestBit) != 0 ? 1u << lane : 0u;
        }
        EXPECT_EQ(always_lanes(packet), expected);
    }
    EXPECT_EQ(always_lanes(cell[0]) | (always_lanes(cell[1]) << 4), 0b10010010u);
    // A ray that meets none of the finite triangles keeps exactly the always lanes.
    const Ray away{{0.5, 0.25, 0.25}, {0, -1, 0}};
    const FloatRay float_ray(away, packets.scale());
    ASSERT_TRUE(float_ray.usable);
    EXPECT_EQ(static_cast<unsigned>(cell_packet_candidates(cell[0], float_ray)), 0b0010u);
    EXPECT_EQ(static_cast<unsigned>(cell_packet_candidates(cell[1], float_ray)), 0b1001u);
#ifdef RT_VOXEL_AVX2
    if (cpu_has_avx2_for_cells()) {
        EXPECT_EQ(cell_pair_candidates(cell.data(), float_ray), 0b10010010u);
    }
#endif
}

#ifdef RT_VOXEL_AVX2
TEST(CellPackets, PairTestAgreesWithTheFourWideTestLaneForLane) {
    if (!cpu_has_avx2_for_cells()) {
        GTEST_SKIP() << "no AVX2 on this CPU";
    }
    std::mt19937 rng(47);
    const Scene scene = random_polygons(rng, 300);
    std::vector<std::uint32_t> all(scene.polygons.size());
    for (std::uint32_t id = 0; id < all.size(); ++id) {
        all[id] = id;
    }
    const CellPackets packets(scene, 1, 0, [&](std::size_t) { return std::span(all); });
    const std::span<const CellPacket> cell = packets.cell(0).packets;
    ASSERT_GE(cell.size(), 2u);
    std::normal_distribution<double> normal(0.0, 1.0);
    int kept = 0;
    for (int i = 0; i < 2000; ++i) {
        // Through a polygon's first corner, nudged: many lanes near their edges.
        const Polygon& p = scene.polygons[rng() % scene.polygons.size()];
        const Vec3 target =
            scene.corner_position(p, 0) + Vec3{normal(rng), normal(rng), normal(rng)} * 1e-3;
        Ray ray{{normal(rng), normal(rng), normal(rng)}, {}};
        ray.direction = target - ray.origin;
        const FloatRay float_ray(ray, packets.scale());
        ASSERT_TRUE(float_ray.usable);
        for (std::size_t k = 0; k + 1 < cell.size(); ++k) {
            const unsigned pair = cell_pair_candidates(&cell[k], float_ray);
            const auto first = static_cast<unsigned>(cell_packet_candidates(cell[k], float_ray));
            const auto second =
                static_cast<unsigned>(cell_packet_candidates(cell[k + 1], float_ray));
            ASSERT_EQ(pair, first | (second << 4)) << "case " << i << ", packet " << k;
            kept += std::popcount(first);
        }
    }
    EXPECT_GT(kept, 2000) << "too few lanes kept for the test to mean much";
}
#endif

// The cells are filled in parts, one thread a part: the packets, their bounds and the scale must
// not depend on the cut.
TEST(CellPackets, SameForAnyNumberOfThreads) {
    const Scene scene = test::make_triangle_soup(3000, 9);
    // 500 cells of uneven sizes (some empty), polygons shared between cells, bounds in front.
    std::vector<std::vector<std::uint32_t>> slots(500);
    std::mt19937 random(4);
    for (std::size_t c = 0; c < slots.size(); ++c) {
        if (c % 7 == 3) {
            continue;
        }
        for (int k = 0; k < 6; ++k) {
            slots[c].push_back(std::bit_cast<std::uint32_t>(static_cast<float>(c + k)));
        }
        const std::size_t count = 1 + random() % 23;
        for (std::size_t k = 0; k < count; ++k) {
            slots[c].push_back(static_cast<std::uint32_t>(random() % scene.polygons.size()));
        }
    }
    const auto ids_of = [&](std::size_t c) {
        return slots[c].empty() ? std::span<const std::uint32_t>{}
                                : std::span<const std::uint32_t>(slots[c]).subspan(6);
    };
    const CellPackets one(scene, slots.size(), kVoxelBoundsSlots, ids_of, 1);
    for (const int threads : {2, 3, 7}) {
        const CellPackets many(scene, slots.size(), kVoxelBoundsSlots, ids_of, threads);
        EXPECT_EQ(many.scale(), one.scale()) << threads;
        EXPECT_EQ(many.memory_bytes(), one.memory_bytes()) << threads;
        for (std::size_t c = 0; c < slots.size(); ++c) {
            const CellView a = one.cell(c);
            const CellView b = many.cell(c);
            ASSERT_EQ(a.packets.size(), b.packets.size()) << c;
            ASSERT_EQ(a.bounds == nullptr, b.bounds == nullptr) << c;
            if (a.bounds != nullptr) {
                EXPECT_EQ(std::memcmp(a.bounds, b.bounds, 6 * sizeof(float)), 0) << c;
            }
            if (!a.packets.empty()) {  // an empty cell's span may hold null
                EXPECT_EQ(std::memcmp(a.packets.data(), b.packets.data(), a.packets.size_bytes()),
                          0)
                    << c << " on " << threads << " threads";
            }
        }
    }
}

}  // namespace
}  // namespace rt
