// The BVH's packets of eight (bvh_packet_traversal.cpp) against brute force: every lane's answer
// is the single ray's, bit for bit, on random rays, camera rays, rays in a polygon's plane, rays
// that start on polygons, and packets with only some lanes asked; inactive lanes are untouched.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/accel/bvh/bvh.h"
#include "rt/accel/bvh/packet_setup.h"
#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/core/diagnostics.h"
#include "rt/scene/read/load_scene.h"

#include <gtest/gtest.h>

#include "accel/accel_compare.h"
#include "accel/surface_rays.h"
#include "support/meshes/generated_meshes.h"
#include "support/scene_builder.h"
#include "support/temp_dir.h"

namespace rt {
namespace {

using test::RayQuery;

// Which lanes a packet asks: all of them, or a pattern drawn from the packet's index.
std::uint32_t active_lanes(std::size_t packet, bool some_only) {
    if (!some_only) {
        return 0xffu;
    }
    constexpr std::uint32_t kPatterns[] = {0x01u, 0x80u, 0x5au, 0xa5u, 0x7eu, 0x0fu, 0xf0u, 0x33u};
    return kPatterns[packet % 8];
}

// The queries eight to a packet through closest_hit_packet and occluded_packet, each asked lane
// compared with brute force; lanes not asked must keep their marker. Returns how many hit.
int expect_packets_match(const Scene& scene, const Accelerator& accel,
                         const std::vector<RayQuery>& queries, bool some_only) {
    const BruteForce brute(scene);
    TraceCounters counters;
    const Hit marker{-1.0, 0xdeadu};
    int mismatches = 0;
    int hits = 0;
    for (std::size_t first = 0; first < queries.size(); first += kPacketSize) {
        RayPacket packet;
        for (int lane = 0; lane < kPacketSize && first + lane < queries.size(); ++lane) {
            packet.rays[lane] = queries[first + lane].ray;
            packet.t[lane] = queries[first + lane].t;
            packet.active |= 1u << lane;
        }
        packet.active &= active_lanes(first / kPacketSize, some_only);
        PacketHits got;
        got.fill(marker);
        accel.closest_hit_packet(packet, got, counters);
        const std::uint32_t blocked = accel.occluded_packet(packet, counters);
        for (int lane = 0; lane < kPacketSize; ++lane) {
            const bool asked = ((packet.active >> lane) & 1u) != 0;
            const bool lane_blocked = ((blocked >> lane) & 1u) != 0;
            if (!asked) {
                const bool untouched = got[lane] && got[lane]->t == marker.t &&
                                       got[lane]->polygon == marker.polygon && !lane_blocked;
                if (!untouched && ++mismatches <= 5) {
                    ADD_FAILURE() << "lane " << lane << " was not asked but changed";
                }
                continue;
            }
            const Ray& ray = packet.rays[lane];
            const std::optional<Hit> want = brute.closest_hit(ray, packet.t[lane], counters);
            hits += want ? 1 : 0;
            const bool same =
                want.has_value() == got[lane].has_value() &&
                (!want || (want->t == got[lane]->t && want->polygon == got[lane]->polygon));
            const bool same_occlusion =
                brute.occluded(ray, packet.t[lane], counters) == lane_blocked;
            if ((!same || !same_occlusion) && ++mismatches <= 5) {
                ADD_FAILURE() << accel.name() << " packet lane " << lane << " differs: origin "
                              << ray.origin.x << ' ' << ray.origin.y << ' ' << ray.origin.z
                              << " direction " << ray.direction.x << ' ' << ray.direction.y << ' '
                              << ray.direction.z << " t " << packet.t[lane].min << ".."
                              << packet.t[lane].max << " brute "
                              << (want ? std::to_string(want->polygon) : "miss") << " got "
                              << (got[lane] ? std::to_string(got[lane]->polygon) : "miss")
                              << (same_occlusion ? "" : " (occluded differs)");
            }
        }
    }
    EXPECT_EQ(mismatches, 0) << "of " << queries.size() << " rays";
    return hits;
}

// Both ways: every lane asked, and the partial patterns.
int expect_both_ways(const Scene& scene, const Accelerator& accel,
                     const std::vector<RayQuery>& queries) {
    expect_packets_match(scene, accel, queries, true);
    return expect_packets_match(scene, accel, queries, false);
}

// Eye rays of a pinhole camera outside the scene's box, in packets of 4x2 neighbouring pixels.
std::vector<RayQuery> camera_queries(const Scene& scene, int width, int height) {
    const auto [lo, hi] = scene.bounds();
    const Vec3 middle = lo * 0.5 + hi * 0.5;
    const double radius = 0.5 * length(hi - lo);
    const Vec3 back = normalize(Vec3{0.3, 0.4, -1.0});
    const Vec3 eye = middle + back * (2.5 * radius);
    const Vec3 forward = -back;
    const Vec3 right = normalize(cross(Vec3{0, 1, 0}, forward));
    const Vec3 up = cross(forward, right);
    std::vector<RayQuery> queries;
    for (int y = 0; y < height; y += 2) {
        for (int x = 0; x < width; x += 4) {
            for (int dy = 0; dy < 2; ++dy) {
                for (int dx = 0; dx < 4; ++dx) {
                    const double u = (2.0 * (x + dx + 0.5) / width - 1.0) * 0.3;
                    const double v = (1.0 - 2.0 * (y + dy + 0.5) / height) * 0.25;
                    queries.push_back({{eye, forward + right * u + up * v}, Interval{}});
                }
            }
        }
    }
    return queries;
}

TEST(BvhPackets, RandomRays) {
    for (const std::uint32_t count : {1u, 100u, 1000u}) {
        const Scene scene = test::make_triangle_soup(count, count);
        const Bvh bvh(scene);
        expect_both_ways(scene, bvh, test::random_queries(scene, 2000, count));
    }
    const Scene sphere = test::make_tessellated_sphere(2000);
    expect_both_ways(sphere, Bvh(sphere), test::random_queries(sphere, 2000, 3));
    const Scene quads = test::make_sphere({0.25, -0.5, 1.0}, 2.0, 12, 20, false);
    expect_both_ways(quads, Bvh(quads), test::random_queries(quads, 2000, 4));
}

TEST(BvhPackets, CameraRays) {
    const Scene sphere = test::make_tessellated_sphere(2000);
    EXPECT_GT(expect_both_ways(sphere, Bvh(sphere), camera_queries(sphere, 64, 48)), 1000);
    const Scene soup = test::make_triangle_soup(1000, 9);
    EXPECT_GT(expect_both_ways(soup, Bvh(soup), camera_queries(soup, 64, 48)), 500);
    Diagnostics diagnostics;
    const Scene cubes =
        load_scene(test::source_dir() / "scenes" / "twocubes.scn", ReaderDialect{}, diagnostics);
    ASSERT_FALSE(cubes.polygons.empty());
    EXPECT_GT(expect_both_ways(cubes, Bvh(cubes), camera_queries(cubes, 64, 48)), 200);
}

// Triangles whose corners lie too far apart in the positions for the packet's 16-bit steps
// (lane_corners.h) go to the scene for their corners; the others keep theirs.
TEST(BvhPackets, CornersFarApartInThePositions) {
    Scene soup = test::make_triangle_soup(2000, 31);
    test::scatter_positions(soup, 30, 7);
    const Bvh bvh(soup);
    expect_both_ways(soup, bvh, test::random_queries(soup, 2000, 8));
    EXPECT_GT(expect_both_ways(soup, bvh, camera_queries(soup, 64, 48)), 500);
}

TEST(BvhPackets, GrazingRays) {
    // Rays from corner to corner of a tilted fan lie in its plane (grazing hits), and
    // axis-parallel rays run along the faces and edges of a box of quads.
    test::SceneBuilder b;
    const Vec3 centre{0.1, 0.2, 0.3};
    const Vec3 u = normalize(Vec3{1, 0.3, 0.2});
    const Vec3 v = normalize(cross(Vec3{0.1, 0.7, 0.4}, u));
    std::vector<Vec3> rim;
    for (int j = 0; j < 12; ++j) {
        const double phi = 2 * 3.141592653589793 * j / 12;
        rim.push_back(centre + u * std::cos(phi) + v * (0.7 * std::sin(phi)));
    }
    for (int j = 0; j < 12; ++j) {
        b.add_polygon({centre, rim[j], rim[(j + 1) % 12]});
    }
    const Scene& fan = b.scene();
    std::vector<RayQuery> queries;
    for (std::size_t i = 0; i < fan.positions.size(); ++i) {
        for (std::size_t j = 0; j < fan.positions.size(); ++j) {
            if (i != j) {
                const Vec3 a = fan.positions[i];
                const Vec3 d = fan.positions[j] - a;
                for (const double back : {0.0, 0.5, 2.0}) {
                    queries.push_back({{a - d * back, d}, Interval{}});
                    queries.push_back({{a - d * back, d}, Interval{1e-12, 0.9}});
                }
            }
        }
    }
    EXPECT_GT(expect_both_ways(fan, Bvh(fan), queries), 100);

    const Scene box = test::make_box({0, 0, 0}, {1, 1, 1}, false);
    std::vector<RayQuery> along;
    for (int axis = 0; axis < 3; ++axis) {
        for (const double a : {0.0, 0.5, 1.0}) {
            for (const double c : {0.0, 0.25, 1.0}) {
                Vec3 origin{a, c, a};
                origin[axis] = -1.0;
                Vec3 direction{0, 0, 0};
                direction[axis] = 1.0;
                along.push_back({{origin, direction}, Interval{}});
                origin[axis] = 2.0;
                direction[axis] = -1.0;
                along.push_back({{origin, direction}, Interval{}});
            }
        }
    }
    EXPECT_GT(expect_both_ways(box, Bvh(box), along), 10);
}

TEST(BvhPackets, RaysStartingOnPolygons) {
    // Neighbouring surface rays share packets as the renderer's shadow feelers would.
    const Scene sphere = test::make_tessellated_sphere(2000);
    std::vector<RayQuery> queries;
    for (const test::SurfaceRay& r : test::surface_rays(sphere, 2000, 21)) {
        queries.push_back({r.ray, r.t});
    }
    // And rays that the polygon they leave would take back if the packet lanes did not skip it.
    for (const test::SurfaceRay& r : test::grazing_surface_rays(sphere, 1000, 22)) {
        queries.push_back({r.ray, r.t});
    }
    expect_both_ways(sphere, Bvh(sphere), queries);
}

// Scales where the float tests give up (every polygon tested exactly), polygons no box holds (a
// NaN or infinite corner: every ray tests them), twisted and zero-normal polygons, and an empty
// scene: lanes fall back to the single ray's path, and still answer as brute force.
TEST(BvhPackets, ScenesTheFloatTestsCannotCover) {
    for (const double scale : {1e-30, 1e15, 1e200}) {
        SCOPED_TRACE(scale);
        Scene scene = test::make_triangle_soup(200, 9);
        for (Vec3& p : scene.positions) {
            p = p * scale;
        }
        expect_both_ways(scene, Bvh(scene), test::random_queries(scene, 800, 23));
    }
    Scene with_nan = test::make_triangle_soup(100, 10);
    with_nan.positions[5].y = std::numeric_limits<double>::quiet_NaN();
    with_nan.positions[9].x = std::numeric_limits<double>::infinity();
    expect_both_ways(with_nan, Bvh(with_nan), test::random_queries(with_nan, 800, 24));
    Scene flat = test::make_triangle_soup(300, 31);
    for (Polygon& p : flat.polygons) {
        p.normal = Vec3{0, 0, 0};
    }
    expect_both_ways(flat, Bvh(flat), test::random_queries(flat, 800, 25));
    const Scene empty;
    RayPacket packet;
    packet.active = 0xffu;
    PacketHits hits;
    TraceCounters counters;
    const Bvh none(empty);
    none.closest_hit_packet(packet, hits, counters);
    for (const std::optional<Hit>& hit : hits) {
        EXPECT_FALSE(hit);
    }
    EXPECT_EQ(none.occluded_packet(packet, counters), 0u);
}

// The packet's vectorised set-up, by `path`, must give each lane exactly FloatRay's values: the
// filters' error bounds are argued for those.
void expect_set_up_equals_float_ray(bvh::SetUpPath path) {
    std::mt19937_64 random(17);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-60, 60);
    int checked = 0;
    int same_axes_packets = 0;
    for (int round = 0; round < 500; ++round) {
        RayPacket packet;
        packet.active = 0xffu;
        for (int lane = 0; lane < kPacketSize; ++lane) {
            const double scale = std::ldexp(1.0, exponent(random));
            Vec3 d{unit(random) * scale, unit(random) * scale, unit(random) * scale};
            // Most rounds mix the lanes' largest axes; one in four gives every lane the same one
            // (x, y or z in turn), as coherent packets have, so same_axes is asked both ways.
            if (round % 4 == 1) {
                d.x *= 4.0;
            } else if (round % 4 == 2) {
                d.y *= 4.0;
            } else if (round % 4 == 3 && round % 8 == 3) {
                d.z *= 4.0;
            }
            if (lane == 1 && round % 4 != 2) {
                d.y = 0.0;  // an axis-parallel component: the inverse is clamped
            }
            packet.rays[lane] = {Vec3{unit(random), unit(random), unit(random)} * 100.0, d};
            packet.t[lane] = Interval{unit(random) + 1.0, 1e3 * (unit(random) + 2.0)};
        }
        if (round % 7 == 0) {
            packet.rays[2].direction = Vec3{0, 0, 0};  // unusable: left to the single path
        }
        packet.t[3] = Interval{};  // as the lab and the renderer ask
        packet.t[4] = Interval{-kBeyondAnyScene, kBeyondAnyScene};
        packet.t[5] = Interval{1e-9, std::nextafter(1.0, 0.0)};  // as shadow feelers
        const double scene_scale = std::ldexp(1.0, exponent(random) / 3);
        bvh::PacketValues v{};
        const std::uint32_t lanes = bvh::set_up_packet(packet, scene_scale, v, path);
        int first_kz = -1;
        bool same_axes = true;
        for (int lane = 0; lane < kPacketSize; ++lane) {
            const FloatRay f(packet.rays[lane], scene_scale);
            ASSERT_EQ(f.usable, ((lanes >> lane) & 1u) != 0) << "lane " << lane;
            if (!f.usable) {
                continue;
            }
            ++checked;
            first_kz = first_kz < 0 ? f.kz : first_kz;
            same_axes = same_axes && f.kz == first_kz;
            // The lane's FloatRay, as a lane that goes on alone takes it (packet_setup.h).
            const FloatRay g = bvh::lane_float_ray(v, lane);
            EXPECT_TRUE(g.usable);
            EXPECT_EQ(f.scale_t, g.scale_t);
            for (int k = 0; k < 3; ++k) {
                EXPECT_EQ(f.origin[k], g.origin[k]);
                EXPECT_EQ(f.inverse[k], g.inverse[k]);
                EXPECT_EQ(f.slab_margin[k], g.slab_margin[k]);
            }
            EXPECT_EQ(f.negative, g.negative);
            EXPECT_EQ(f.kx, g.kx);
            EXPECT_EQ(f.ky, g.ky);
            EXPECT_EQ(f.kz, g.kz);
            EXPECT_EQ(f.shear_x, g.shear_x);
            EXPECT_EQ(f.shear_y, g.shear_y);
            EXPECT_EQ(f.edge_margin_linear, g.edge_margin_linear);
            EXPECT_EQ(f.edge_margin_constant, g.edge_margin_constant);
            EXPECT_EQ(f.scaled_down(packet.t[lane].min), v.t_min[lane]);
            EXPECT_EQ(f.scaled_up(packet.t[lane].max), v.t_max[lane]);
        }
        EXPECT_EQ(same_axes, v.same_axes) << "round " << round;
        same_axes_packets += same_axes ? 1 : 0;
    }
    EXPECT_GT(checked, 3500);
    EXPECT_GT(same_axes_packets, 50);  // 82 with this seed
    EXPECT_LT(same_axes_packets, 450);
}

TEST(BvhPackets, SetUpEqualsFloatRayLaneForLane) {
    expect_set_up_equals_float_ray(bvh::SetUpPath::FourLanes);
}

TEST(BvhPackets, EightLaneSetUpEqualsFloatRayLaneForLane) {
    if (!bvh::set_up_path_available(bvh::SetUpPath::EightLanes)) {
        GTEST_SKIP() << "this CPU has no AVX-512";
    }
    expect_set_up_equals_float_ray(bvh::SetUpPath::EightLanes);
}

// Both set-ups, on extremes as well (NaN, infinite, huge, tiny and zero values), choose the same
// lanes and give them the same bits.
TEST(BvhPackets, SetUpPathsAgreeOnEveryValue) {
    if (!bvh::set_up_path_available(bvh::SetUpPath::EightLanes)) {
        GTEST_SKIP() << "this CPU has no AVX-512";
    }
    std::mt19937_64 random(29);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> pick(0, 9);
    std::uniform_int_distribution<int> exponent(-1100, 1100);
    const auto value = [&]() {
        switch (pick(random)) {
            case 0:
                return std::numeric_limits<double>::quiet_NaN();
            case 1:
                return unit(random) < 0.0 ? -HUGE_VAL : HUGE_VAL;
            case 2:
                return 0.0;
            case 3:
            case 4:
                return std::ldexp(unit(random), exponent(random));
            default:
                return unit(random) * 10.0;
        }
    };
    int set_up = 0;
    for (int round = 0; round < 4000; ++round) {
        RayPacket packet;
        packet.active = round % 5 == 0 ? 0x5au : 0xffu;
        for (int lane = 0; lane < kPacketSize; ++lane) {
            packet.rays[lane] = {Vec3{value(), value(), value()}, Vec3{value(), value(), value()}};
            const double a = value();
            const double b = value();
            packet.t[lane] = Interval{std::min(a, b), std::max(a, b)};
        }
        const double scene_scale = std::ldexp(1.0, exponent(random) / 20);
        bvh::PacketValues four{};
        bvh::PacketValues eight{};
        const std::uint32_t lanes =
            bvh::set_up_packet(packet, scene_scale, four, bvh::SetUpPath::FourLanes);
        ASSERT_EQ(lanes, bvh::set_up_packet(packet, scene_scale, eight, bvh::SetUpPath::EightLanes))
            << "round " << round;
        if (lanes != 0) {
            EXPECT_EQ(four.same_axes, eight.same_axes) << "round " << round;
        }
        const auto same = [](float x, float y) {
            return std::bit_cast<std::uint32_t>(x) == std::bit_cast<std::uint32_t>(y);
        };
        for (int lane = 0; lane < kPacketSize; ++lane) {
            if (((lanes >> lane) & 1u) == 0) {
                continue;
            }
            ++set_up;
            for (int k = 0; k < 3; ++k) {
                EXPECT_TRUE(same(four.origin[k][lane], eight.origin[k][lane]));
                EXPECT_TRUE(same(four.inverse[k][lane], eight.inverse[k][lane]));
                EXPECT_TRUE(same(four.margin[k][lane], eight.margin[k][lane]));
            }
            EXPECT_TRUE(same(four.t_min[lane], eight.t_min[lane])) << "round " << round;
            EXPECT_TRUE(same(four.t_max[lane], eight.t_max[lane])) << "round " << round;
            EXPECT_TRUE(same(four.shear_x[lane], eight.shear_x[lane]));
            EXPECT_TRUE(same(four.shear_y[lane], eight.shear_y[lane]));
            EXPECT_TRUE(same(four.edge_linear[lane], eight.edge_linear[lane]));
            EXPECT_TRUE(same(four.edge_constant[lane], eight.edge_constant[lane]));
            EXPECT_EQ(std::bit_cast<std::uint64_t>(four.scale_t[lane]),
                      std::bit_cast<std::uint64_t>(eight.scale_t[lane]));
            EXPECT_EQ(four.kx[lane], eight.kx[lane]);
            EXPECT_EQ(four.ky[lane], eight.ky[lane]);
            EXPECT_EQ(four.kz[lane], eight.kz[lane]);
        }
    }
    EXPECT_GT(set_up, 1000);
}

TEST(BvhPackets, TheFallbackLoopsOverSingleRays) {
    const Scene soup = test::make_triangle_soup(300, 2);
    const BruteForce brute(soup);
    expect_both_ways(soup, brute, test::random_queries(soup, 800, 5));
}

}  // namespace
}  // namespace rt
