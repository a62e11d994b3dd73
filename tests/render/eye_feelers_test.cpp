// The shadow feelers from eye hits are planned and asked eight at a time when the method walks
// packets (RayTracer::eye_feelers): the picture and the feelers' own counts must be those of the
// feelers asked one by one, whatever the lights, the surfaces in the way and the switches.
#include <atomic>
#include <cstdint>
#include <vector>

#include "rt/accel/bvh/bvh.h"
#include "rt/render/renderer.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

// The BVH's answers, with its packet walk on or off (off: the renderer asks every feeler alone),
// counting the packets that are not eye rays', the feelers'.
class SwitchablePackets : public Accelerator {
public:
    SwitchablePackets(const Scene& scene, bool packets) : bvh_(scene), packets_(packets) {}
    std::string_view name() const override { return "bvh"; }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override {
        return bvh_.closest_hit(ray, t, counters);
    }
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override {
        return bvh_.occluded(ray, t, counters);
    }
    void closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                            TraceCounters& counters) const override {
        ++feeler_packets;
        bvh_.closest_hit_packet(packet, hits, counters);
    }
    void eye_ray_closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                    TraceCounters& counters) const override {
        bvh_.closest_hit_packet(packet, hits, counters);
    }
    bool walks_packets() const override { return packets_ && bvh_.walks_packets(); }

    mutable std::atomic<std::uint64_t> feeler_packets{0};

private:
    Bvh bvh_;
    bool packets_;
};

struct Rendered {
    std::vector<float> pixels;
    TraceCounters feelers;
    std::uint64_t feeler_packets = 0;
};

Rendered render_with(const Scene& scene, const ShadingSettings& shading, bool packets) {
    const SwitchablePackets accel(scene, packets);
    RenderSettings settings;
    settings.shading = shading;
    settings.window = {0, 0, scene.view.width - 1, scene.view.height - 1};
    settings.threads = 2;
    RenderObserver observer;
    RenderStatistics statistics;
    const Film film = render(scene, accel, settings, observer, statistics);
    return {film.data(), statistics.by_kind[RayKind::ShadowFeeler], accel.feeler_packets.load()};
}

// A floor, a glass pane and an opaque block over it, and a square lamp above: feelers from the
// floor meet the lamp, the pane (and go on through it) or the block.
Scene lit_room() {
    test::SceneBuilder b;
    Attribute floor;
    floor.color = {0.8, 0.7, 0.6};
    floor.diffuse = 0.9;
    floor.specular = 0.2;
    Attribute glass;
    glass.color = {0.6, 0.9, 0.7};
    glass.diffuse = 0.1;
    glass.transmission = 0.7;
    glass.refraction_index = {1.0, 1.0, 1.0};
    Attribute lamp;
    lamp.color = {1, 1, 1};
    lamp.emission = 1.0;
    b.scene().attributes = {floor, glass, lamp, floor};
    const auto square = [&](double y, double x0, double x1, double z0, double z1, const Vec3& n,
                            std::uint32_t attribute) {
        b.add_polygon({{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}}, n, attribute);
    };
    square(0.0, -4, 4, -4, 4, {0, 1, 0}, 0);
    square(1.0, -2, 0.5, -2, 0.5, {0, 1, 0}, 1);  // the pane, seen from both sides
    square(1.5, 0.8, 2.0, -1, 1, {0, 1, 0}, 3);   // the block's top
    square(1.4, 0.8, 2.0, -1, 1, {0, -1, 0}, 3);  // and its underside
    square(3.0, -0.5, 0.5, -0.5, 0.5, {0, -1, 0}, 2);
    Scene scene = b.scene();
    scene.header.lghtick = 1;  // a light at each of the lamp's corners
    scene.header.maxdepth = 2;
    scene.view.eye = {0.3, 5.0, -6.0};
    scene.view.look = {0, 0, 0};
    scene.view.width = 48;
    scene.view.height = 36;
    scene.view.sample_resolution_x = 2;
    scene.view.sample_resolution_y = 2;
    return scene;
}

void expect_same_render(const Scene& scene, const ShadingSettings& shading, bool planned) {
    const Rendered alone = render_with(scene, shading, false);
    const Rendered packed = render_with(scene, shading, true);
    EXPECT_EQ(alone.feeler_packets, 0u);
    if (planned) {
        EXPECT_GT(packed.feeler_packets, 0u);  // the feelers did go eight at a time
    } else {
        EXPECT_EQ(packed.feeler_packets, 0u);
    }
    ASSERT_EQ(alone.pixels.size(), packed.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < alone.pixels.size(); ++i) {
        differing += alone.pixels[i] != packed.pixels[i] ? 1 : 0;
    }
    EXPECT_EQ(differing, 0u) << "of " << alone.pixels.size() << " channels";
    // The same feelers, meeting the same polygons (the walks' node counts may differ).
    EXPECT_EQ(alone.feelers.rays, packed.feelers.rays);
    EXPECT_EQ(alone.feelers.hits, packed.feelers.hits);
}

TEST(EyeFeelers, FeelersAskedEightAtATimeGiveTheSamePicture) {
    if (!SwitchablePackets(lit_room(), true).walks_packets()) {
        GTEST_SKIP() << "no AVX2: the BVH asks packets lane by lane";
    }
    expect_same_render(lit_room(), ShadingSettings{}, true);
}

TEST(EyeFeelers, TheSameWithFarSideFeelersWarnLightsAndFeelersThatStopAtTheFirstPolygon) {
    if (!SwitchablePackets(lit_room(), true).walks_packets()) {
        GTEST_SKIP() << "no AVX2: the BVH asks packets lane by lane";
    }
    ShadingSettings far_side;
    far_side.far_side_feelers = true;  // -T
    expect_same_render(lit_room(), far_side, true);
    ShadingSettings warn;
    warn.warn.mode = WarnMode::Thibadeau;  // -Wt: feelers aimed at a displaced source
    warn.warn.displacement = 0.3;
    expect_same_render(lit_room(), warn, true);
    ShadingSettings stop;
    stop.feelers_stop_at_transparent = true;  // -Dt
    stop.both_sides_emit = false;             // -Db
    expect_same_render(lit_room(), stop, true);
}

TEST(EyeFeelers, FuzzyFeelersAreNotPlannedAhead) {
    ShadingSettings fuzzy;  // -F: random directions, drawn while shading
    fuzzy.fuzzy.angle = 0.05;
    fuzzy.fuzzy.count = 3;
    expect_same_render(lit_room(), fuzzy, false);
}

}  // namespace
}  // namespace rt
