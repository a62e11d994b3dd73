// The packet walk's node tests against the slab test in double, on lines through the corners of a
// node's boxes (the tightest case for their margins): each lane's own test (test_children) keeps
// every child whose box the lane's line meets within its interval, entered no later than the
// exact entry, and the test over the whole packet (children_packet_may_meet) keeps every child
// some lane's own test keeps. Neither widens by more than the slab margin (float_ray.cpp, part 2).
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))

#include "rt/accel/bvh/packet_node_tests.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>

#include <gtest/gtest.h>

#include "accel/bvh/random_wide_node.h"

namespace rt::bvh::packet {
namespace {

using test::exact_slab;
using test::random_corner;
using test::random_point;
using test::random_wide_node;

constexpr double kSceneScale = 16.0;

struct Tally {
    int lanes_met = 0;
    int packets_bounded = 0;
};

// One packet: eight lines from origins near `centre` through corners of box `aimed` (with no
// spread, eight copies of the first).
__attribute__((target("avx2"))) void check_packet(std::mt19937& rng, const WideNode& node,
                                                  int aimed, const Vec3& centre, float spread,
                                                  Tally& tally) {
    RayPacket packet;
    for (int lane = 0; lane < kPacketSize; ++lane) {
        const Vec3 origin = centre + random_point(rng, spread);
        const Vec3 corner = random_corner(rng, node, aimed);
        packet.rays[lane] = Ray{origin, normalize(corner - origin)};
        // Half the lanes' intervals end exactly where the line meets the corner.
        const double reach = lane % 2 == 0 ? length(corner - origin) : 1e30;
        packet.t[lane] = Interval{0.0, reach};
    }
    if (spread == 0.0f) {
        // Eight copies of one line: the bound over the lanes is that lane's own test.
        std::fill(packet.rays.begin() + 1, packet.rays.end(), packet.rays[0]);
        std::fill(packet.t.begin() + 1, packet.t.end(), packet.t[0]);
    }
    packet.active = 0xffU;
    PacketValues v{};
    const std::uint32_t lanes = set_up_packet(packet, kSceneScale, v);
    std::array<ChildHits, kNodeWidth> out{};
    const int count = test_children(node, v, lanes, 0xffU, out.data());
    std::uint32_t kept = 0;
    for (int i = 0; i < count; ++i) {
        kept |= 1U << out[static_cast<std::size_t>(i)].child;
    }
    EXPECT_EQ(kept & 0x80U, 0U) << "the empty slot was entered";
    for (int lane = 0; lane < kPacketSize; ++lane) {
        if ((lanes >> lane & 1U) == 0) {
            continue;
        }
        const Ray& ray = packet.rays[lane];
        for (int c = 0; c < 7; ++c) {
            const test::Slab slab = exact_slab(node, c, ray);
            const double enter = slab.enter;
            const double exit = slab.exit;
            const Interval t = packet.t[lane];
            if (!(enter <= exit && exit >= t.min && enter <= t.max)) {
                continue;
            }
            ++tally.lanes_met;
            const ChildHits* hit = std::find_if(
                out.data(), out.data() + count,
                [&](const ChildHits& h) { return h.child == static_cast<std::uint32_t>(c); });
            ASSERT_NE(hit, out.data() + count) << "child " << c << " dropped by every lane";
            EXPECT_NE(hit->rays >> lane & 1U, 0U) << "lane " << lane << " child " << c;
            EXPECT_LE(hit->entry[lane], enter * v.scale_t[lane]) << "lane " << lane;
        }
    }
    PacketBounds b;
    bound_packet(v, b);
    if (b.usable && lanes == 0xffU) {
        ++tally.packets_bounded;
        const std::uint32_t may = children_packet_may_meet(node, b);
        EXPECT_EQ(kept & ~may, 0U) << "the packet's bound dropped a child a lane keeps";
    }
}

TEST(PacketNodeTests, KeepEveryBoxWhoseCornerALaneGrazes) {
    if (!__builtin_cpu_supports("avx2")) {
        GTEST_SKIP() << "the packet walk needs AVX2";
    }
    std::mt19937 rng(4242);
    Tally tally;
    for (int trial = 0; trial < 3000; ++trial) {
        const WideNode node = random_wide_node(rng);
        const int aimed = static_cast<int>(rng() % 7);
        // Coherent packets from inside and far outside the scene, and scattered ones.
        const float reach = trial % 3 == 0 ? 14.0f : 1000.0f;
        const Vec3 centre = random_point(rng, reach);
        const float spread = trial % 4 == 0 ? 0.0f : trial % 2 == 0 ? 0.01f : 2.0f;
        check_packet(rng, node, aimed, centre, spread, tally);
    }
    EXPECT_GT(tally.lanes_met, 15000);
    EXPECT_GT(tally.packets_bounded, 1000);
}

}  // namespace
}  // namespace rt::bvh::packet

#endif
