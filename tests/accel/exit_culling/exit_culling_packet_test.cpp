// Packets through exit culling: each asked lane gets the single ray's answer (closest_hit and
// occluded through the same ExitCulling, one ray at a time), culled lanes are counted as the
// single rays count them, -de checks them the same way, and the lanes not culled reach the
// wrapped accelerator as one packet with the reduced mask. Over the BVH (an AVX2 packet walk)
// and over brute force (lane by lane), with every lane asked and with partial masks.
#include <bit>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/accel/bvh/bvh.h"
#include "rt/accel/exit_culling/exit_culling.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"
#include "accel/surface_rays.h"

namespace rt::test {
namespace {

// Passes every call on to `inner`, noting how it was asked: the packets' masks and the single
// rays. Its packet calls go to inner's packet calls, so a packet walk below still serves them.
class RecordingAccelerator : public Accelerator {
public:
    explicit RecordingAccelerator(std::unique_ptr<Accelerator> inner) : inner_(std::move(inner)) {}

    std::string_view name() const override { return inner_->name(); }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override {
        ++single_rays;
        return inner_->closest_hit(ray, t, counters);
    }
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override {
        ++single_rays;
        return inner_->occluded(ray, t, counters);
    }
    void closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                            TraceCounters& counters) const override {
        masks.push_back(packet.active);
        inner_->closest_hit_packet(packet, hits, counters);
    }
    std::uint32_t occluded_packet(const RayPacket& packet, TraceCounters& counters) const override {
        masks.push_back(packet.active);
        return inner_->occluded_packet(packet, counters);
    }

    mutable std::vector<std::uint32_t> masks;
    mutable int single_rays = 0;

private:
    std::unique_ptr<Accelerator> inner_;
};

enum class Method { Bvh, BruteForce };

std::unique_ptr<Accelerator> make_method(const Scene& scene, Method method) {
    if (method == Method::Bvh) {
        return std::make_unique<Bvh>(scene);
    }
    return std::make_unique<BruteForce>(scene);
}

// Which lanes a packet asks: all of them, or a pattern drawn from the packet's index.
std::uint32_t asked_lanes(std::size_t packet, bool some_only) {
    if (!some_only) {
        return 0xffu;
    }
    constexpr std::uint32_t kPatterns[] = {0x01u, 0x80u, 0x5au, 0xa5u, 0x7eu, 0x0fu, 0xf0u, 0x33u};
    return kPatterns[packet % 8];
}

std::vector<TestRay> rays_for(const Scene& scene, std::uint64_t seed) {
    std::vector<TestRay> rays = make_test_rays(scene, seed, 4000);
    for (const SurfaceRay& r : surface_rays(scene, 2000, seed + 1)) {
        rays.push_back({r.ray, r.t});
    }
    return rays;
}

bool same(const std::optional<Hit>& a, const std::optional<Hit>& b) {
    return a.has_value() == b.has_value() && (!a || (a->t == b->t && a->polygon == b->polygon));
}

struct Tally {
    int mismatches = 0;
    int culled_lanes = 0;
    int guarded_lanes = 0;  ///< answered from their guards
    int passed_lanes = 0;
    int mixed_packets = 0;  ///< packets with lanes both culled and passed on
};

// What a lane the packet does not ask holds before and after.
constexpr Hit kUnasked{-1.0, 0xdeadu};

struct LaneRoutes {
    std::uint32_t culled = 0;
    std::uint32_t guarded = 0;
};

// Each lane of the packet against the single ray's answer through `single`: the lanes not asked
// must keep kUnasked. Returns the lanes the single path culled and answered from their guards.
LaneRoutes check_lanes(const ExitCulling& single, const RayPacket& packet, const PacketHits& got,
                       std::uint32_t blocked, std::size_t index, TraceCounters& single_counters,
                       Tally& tally) {
    LaneRoutes routes;
    for (int lane = 0; lane < kPacketSize; ++lane) {
        const bool asked = ((packet.active >> lane) & 1u) != 0;
        const bool lane_blocked = ((blocked >> lane) & 1u) != 0;
        if (!asked) {
            if (!same(got[lane], kUnasked) || lane_blocked) {
                ++tally.mismatches;
                ADD_FAILURE() << "lane " << lane << " was not asked but changed";
            }
            continue;
        }
        const std::uint64_t culled_before = single_counters.culled_exits;
        const std::uint64_t guarded_before = single_counters.guard_answers;
        const std::optional<Hit> want =
            single.closest_hit(packet.rays[lane], packet.t[lane], single_counters);
        const bool want_blocked =
            single.occluded(packet.rays[lane], packet.t[lane], single_counters);
        // A culled ray is culled as a nearest-hit ray and as a feeler alike.
        routes.culled |= single_counters.culled_exits != culled_before ? 1u << lane : 0u;
        // So is a ray answered from its guards.
        routes.guarded |= single_counters.guard_answers != guarded_before ? 1u << lane : 0u;
        if ((!same(want, got[lane]) || want_blocked != lane_blocked) && ++tally.mismatches <= 5) {
            ADD_FAILURE() << "lane " << lane << " of packet " << index
                          << " differs from the single ray";
        }
    }
    return routes;
}

// The rays eight to a packet through `packed`, against single rays through `single` (built the
// same way); both counters are compared where the method counts a packet as its rays.
Tally compare(const Scene& scene, Method method, bool some_only, bool check_culled) {
    ExitCullingSettings settings;
    settings.check_culled = check_culled;
    auto recorder = std::make_unique<RecordingAccelerator>(make_method(scene, method));
    const RecordingAccelerator& recorded = *recorder;
    const ExitCulling packed(scene, std::move(recorder), settings);
    const ExitCulling single(scene, make_method(scene, method), settings);
    const std::vector<TestRay> rays = rays_for(scene, 31);
    TraceCounters packet_counters;
    TraceCounters single_counters;
    Tally tally;
    for (std::size_t first = 0; first < rays.size(); first += kPacketSize) {
        RayPacket packet;
        for (int lane = 0; lane < kPacketSize && first + lane < rays.size(); ++lane) {
            packet.rays[lane] = rays[first + lane].ray;
            packet.t[lane] = rays[first + lane].t;
            packet.active |= 1u << lane;
        }
        packet.active &= asked_lanes(first / kPacketSize, some_only);
        PacketHits got;
        got.fill(kUnasked);
        recorded.masks.clear();
        packed.closest_hit_packet(packet, got, packet_counters);
        const std::uint32_t blocked = packed.occluded_packet(packet, packet_counters);
        const auto [culled, guarded] =
            check_lanes(single, packet, got, blocked, first / kPacketSize, single_counters, tally);
        const std::uint32_t passed = packet.active & ~(culled | guarded);
        tally.culled_lanes += std::popcount(culled);
        tally.guarded_lanes += std::popcount(guarded);
        tally.passed_lanes += std::popcount(passed);
        tally.mixed_packets += culled != 0 && passed != 0 ? 1 : 0;
        // One closest-hit and one occlusion packet with the lanes neither culled nor answered from
        // their guards, or none at all.
        const std::vector<std::uint32_t> want_masks =
            passed != 0 ? std::vector<std::uint32_t>{passed, passed} : std::vector<std::uint32_t>{};
        EXPECT_EQ(recorded.masks, want_masks) << "packet " << first / kPacketSize;
    }
    EXPECT_EQ(packet_counters.culled_exits, single_counters.culled_exits);
    EXPECT_EQ(packet_counters.guard_answers, single_counters.guard_answers);
    if (method == Method::BruteForce) {  // the BVH's packet walk counts nodes its own way
        EXPECT_EQ(packet_counters.polygon_tests, single_counters.polygon_tests);
        EXPECT_EQ(packet_counters.nodes_visited, single_counters.nodes_visited);
        EXPECT_EQ(packet_counters.hits, single_counters.hits);
    }
    // With -de a culled or guarded ray is traced again one at a time, as the single path does;
    // else never.
    EXPECT_EQ(recorded.single_rays,
              check_culled ? 2 * (tally.culled_lanes + tally.guarded_lanes) : 0);
    const ExitCullingStatistics p = packed.statistics();
    const ExitCullingStatistics s = single.statistics();
    EXPECT_EQ(p.checked, s.checked);
    EXPECT_EQ(p.checked, check_culled ? 2u * static_cast<unsigned>(tally.culled_lanes) : 0u);
    EXPECT_EQ(p.violations, 0u);
    EXPECT_EQ(p.guards_checked, s.guards_checked);
    EXPECT_EQ(p.guard_violations, 0u);
    return tally;
}

struct PacketCase {
    std::string name;
    Scene (*make)();
};

Scene soup() {
    return make_soup(11, 300);
}
Scene sphere() {
    return make_sphere({1, 2, 3}, 5.0, 12, 24, false);
}
Scene boxes() {
    return make_boxes(13, 12);
}
Scene twocubes() {
    return load_twocubes();
}

class ExitCullingPackets : public ::testing::TestWithParam<PacketCase> {};

TEST_P(ExitCullingPackets, EachLaneIsTheSingleRaysAnswer) {
    const Scene scene = GetParam().make();
    for (const Method method : {Method::Bvh, Method::BruteForce}) {
        for (const bool some_only : {false, true}) {
            for (const bool check_culled : {false, true}) {
                SCOPED_TRACE(std::string(method == Method::Bvh ? "bvh" : "brute force") +
                             (some_only ? ", some lanes" : ", every lane") +
                             (check_culled ? ", -de" : ""));
                const Tally tally = compare(scene, method, some_only, check_culled);
                EXPECT_EQ(tally.mismatches, 0);
                EXPECT_GT(tally.mixed_packets, 0) << "the test would prove nothing";
                EXPECT_GT(tally.culled_lanes, 0);
                EXPECT_GT(tally.passed_lanes, 0);
                if (scene.polygons.size() <= kMostLeavingTablePolygons) {
                    EXPECT_GT(tally.guarded_lanes, 0);
                }
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ExitCullingPackets,
                         ::testing::Values(PacketCase{"soup", soup}, PacketCase{"sphere", sphere},
                                           PacketCase{"boxes", boxes},
                                           PacketCase{"twocubes", twocubes}),
                         [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace rt::test
