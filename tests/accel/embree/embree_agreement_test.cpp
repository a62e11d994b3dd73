// Embree (comparison only) against brute force: single precision and not watertight against our
// exact test, so it may name another polygon, or none, for rays through edges and corners. It must
// agree on all but a tiny fraction of random rays, with nearly the same t.
#include <cmath>
#include <memory>

#include "rt/accel/brute_force.h"
#include "rt/accel/make_accelerator.h"
#include "rt/core/diagnostics.h"
#include "rt/core/error.h"
#include "rt/scene/read/load_scene.h"

#include <gtest/gtest.h>

#include "accel/accel_compare.h"
#include "support/meshes/generated_meshes.h"
#include "support/scene_builder.h"
#include "support/temp_dir.h"

namespace rt {
namespace {

std::unique_ptr<Accelerator> embree_or_skip(const Scene& scene, unsigned build_threads = 0) {
    try {
        AccelSettings settings;
        settings.kind = AccelKind::Embree;
        settings.build_threads = build_threads;
        return make_accelerator(scene, settings);
    } catch (const NotImplementedError&) {
        return nullptr;
    }
}

// Rays from anywhere in and around the box, in any direction, over the default interval.
void expect_mostly_same(const Scene& scene, int rays, std::uint64_t seed,
                        unsigned build_threads = 0) {
    const std::unique_ptr<Accelerator> embree = embree_or_skip(scene, build_threads);
    if (!embree) {
        GTEST_SKIP() << "this rt was built without Embree";
    }
    const BruteForce brute(scene);
    TraceCounters counters;
    int differ = 0;
    int hits = 0;
    // Only the queries in random directions: the others aim at corners and edges on purpose.
    const std::vector<test::RayQuery> queries = test::random_queries(scene, 2 * rays, seed);
    for (int i = 0; i < 2 * rays; i += 2) {
        test::RayQuery q = queries[i];
        q.t = Interval{};
        const std::optional<Hit> want = brute.closest_hit(q.ray, q.t, counters);
        const std::optional<Hit> got = embree->closest_hit(q.ray, q.t, counters);
        hits += want.has_value();
        const bool same = want.has_value() == got.has_value() &&
                          (!want || (want->polygon == got->polygon &&
                                     std::fabs(want->t - got->t) <= 1e-4 * (1 + want->t)));
        differ += !same;
        differ += brute.occluded(q.ray, q.t, counters) != embree->occluded(q.ray, q.t, counters);
    }
    EXPECT_GT(hits, rays / 20) << "the rays should hit something";
    EXPECT_LE(differ, rays / 100) << "of " << rays << " rays";
}

TEST(EmbreeAgreement, Spheres) {
    expect_mostly_same(test::make_tessellated_sphere(5000), 5000, 1);
    expect_mostly_same(test::make_sphere({1, 2, 3}, 2.0, 10, 16, false), 5000, 2);
}

TEST(EmbreeAgreement, Soup) {
    expect_mostly_same(test::make_triangle_soup(5000, 3), 5000, 3);
}

// --threads 1 reaches Embree's device as "threads=1": a configuration it must accept.
TEST(EmbreeAgreement, BuiltOnOneThread) {
    expect_mostly_same(test::make_triangle_soup(5000, 3), 5000, 3, 1);
}

TEST(EmbreeAgreement, TwoCubes) {
    Diagnostics diagnostics;
    expect_mostly_same(
        load_scene(test::source_dir() / "scenes" / "twocubes.scn", ReaderDialect{}, diagnostics),
        5000, 4);
}

TEST(EmbreeAgreement, EmptyScene) {
    const Scene empty;
    const std::unique_ptr<Accelerator> embree = embree_or_skip(empty);
    if (!embree) {
        GTEST_SKIP() << "this rt was built without Embree";
    }
    TraceCounters counters;
    EXPECT_FALSE(embree->closest_hit({{0, 0, 0}, {0, 0, 1}}, Interval{}, counters));
    EXPECT_FALSE(embree->occluded({{0, 0, 0}, {0, 0, 1}}, Interval{}, counters));
}

// Embree asserts on a ray whose origin is beyond 1.844e18 or not a number; the backend answers a
// miss instead of passing it on.
TEST(EmbreeAgreement, RaysEmbreeCallsInvalidMiss) {
    const Scene sphere = test::make_tessellated_sphere(100);
    const std::unique_ptr<Accelerator> embree = embree_or_skip(sphere);
    if (!embree) {
        GTEST_SKIP() << "this rt was built without Embree";
    }
    TraceCounters counters;
    const double nan = std::nan("");
    for (const Ray& ray : {Ray{{0, 0, -1e19}, {0, 0, 1}}, Ray{{0, 0, nan}, {0, 0, 1}},
                           Ray{{0, 0, -10}, {0, nan, 1}}}) {
        EXPECT_FALSE(embree->closest_hit(ray, Interval{}, counters));
        EXPECT_FALSE(embree->occluded(ray, Interval{}, counters));
    }
    // The same ray from nearer by hits: the sphere is there.
    EXPECT_TRUE(embree->closest_hit({{0, 0, -1e6}, {0, 0, 1}}, Interval{}, counters));
}

// rtcIntersect8 (closest_hit_packet) against rtcIntersect1 lane by lane, with some lanes not
// asked and some rays Embree calls invalid: the same polygon and nearly the same t on all but a
// tiny fraction, misses for the invalid ones, and lanes not asked left as they were.
TEST(EmbreeAgreement, PacketsOfEightAgreeWithSingleRays) {
    const Scene sphere = test::make_tessellated_sphere(5000);
    const std::unique_ptr<Accelerator> embree = embree_or_skip(sphere);
    if (!embree) {
        GTEST_SKIP() << "this rt was built without Embree";
    }
    const std::vector<test::RayQuery> queries = test::random_queries(sphere, 4000, 6);
    TraceCounters counters;
    int differ = 0;
    int hits = 0;
    for (std::size_t first = 0; first + kPacketSize <= queries.size(); first += kPacketSize) {
        RayPacket packet;
        for (int lane = 0; lane < kPacketSize; ++lane) {
            packet.rays[lane] = queries[first + lane].ray;
            packet.t[lane] = Interval{};
        }
        packet.rays[3].origin.z = std::nan("");  // Embree would assert: a miss
        packet.active = (first / kPacketSize) % 3 == 0 ? 0x6du : 0xffu;
        PacketHits got;
        got.fill(Hit{-1.0, 7u});
        embree->closest_hit_packet(packet, got, counters);
        for (int lane = 0; lane < kPacketSize; ++lane) {
            if (((packet.active >> lane) & 1u) == 0) {
                EXPECT_TRUE(got[lane] && got[lane]->t == -1.0) << "lane " << lane;
                continue;
            }
            const std::optional<Hit> want =
                embree->closest_hit(packet.rays[lane], packet.t[lane], counters);
            hits += want.has_value();
            differ += !(want.has_value() == got[lane].has_value() &&
                        (!want || (want->polygon == got[lane]->polygon &&
                                   std::fabs(want->t - got[lane]->t) <= 1e-4 * (1 + want->t))));
            if (lane == 3) {
                EXPECT_FALSE(got[lane]);
            }
        }
    }
    EXPECT_GT(hits, 400);
    EXPECT_LE(differ, 10);
}

}  // namespace
}  // namespace rt
