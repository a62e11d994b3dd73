// Pixel probes, light: the exact value of chosen pixels computed here from the manual's formulas
// and the documented choices (docs/rendering.md), against what the real rt program writes to its
// .gro file. Emission and ambient light (e·C, a·C), the camera, a point lit by one emitter
// (d·C·L·cosθ and the Phong highlight), attenuation on eye rays and shadow feelers (-A, -Da, -Dl),
// lghtick 1 and 2, -Db, and shadows behind opaque and transparent blockers (-Dt).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "integration/pixel_probes.h"
#include "support/probe_scene.h"
#include "support/temp_dir.h"

namespace rt::test::probe {
namespace {

// ---- Emission, ambient light and the camera ----

// Four squares, one per quadrant of the view; the bottom-right one nearer. No lights (lghtick 0)
// and no diffuse weight, so each pixel is (e·C + a·C) times the eye ray's attenuation.
ProbeScene quadrants() {
    ProbeScene s;
    s.attributes = {{.colour = {0.9, 0.3, 0.1}, .a = 0.6},
                    {.colour = {0.2, 0.8, 0.4}, .e = 0.5, .a = 0.2},
                    {.colour = {0.3, 0.5, 0.9}, .e = 0.7, .a = 0.1},
                    {.colour = {0.6, 0.6, 0.2}, .a = 0.4}};
    s.squares = {{0, 20.0, {-20.0, 20.0, 10.0}},          // top left: ambient only
                 {1, 20.0, {20.0, 20.0, 10.0}},           // top right: emits toward the eye
                 {2, 20.0, {-20.0, -20.0, 10.0}, 180.0},  // bottom left: emits, seen from behind
                 {3, 20.0, {20.0, -20.0, 4.0}}};          // bottom right: ambient only, nearer
    return s;
}

// Checks every pixel whose ray clearly meets one square; returns how many.
int check_emission_and_ambient(const ProbeScene& s, const Switches& run) {
    const TempDir dir;
    const GroPixels gro = render_probe(dir, s, run.words);
    int probes = 0;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const Ray ray = pixel_ray(s, x, y);
            const FirstHit hit = first_hit(s, ray);
            if (hit.square == kNoSquare || !hit.clear) {
                continue;
            }
            const ProbeSquare& q = s.squares[static_cast<std::size_t>(hit.square)];
            const ProbeAttribute& a = s.attributes[static_cast<std::size_t>(q.attribute)];
            const bool front = dot(ray.direction, place(q).normal) < 0.0;
            const double emitted = front || run.back_emits ? a.e : 0.0;
            const Colour want = colour_of(a) * ((emitted + a.a) * ray_factor(run, hit.at.t));
            expect_pixel(gro, x, y, want, run.name());
            ++probes;
        }
    }
    return probes;
}

TEST(PixelProbes, EmissionAndAmbientLightThroughTheCamera) {
    const ProbeScene s = quadrants();
    // 24 pixels: all but the middle row and column, which look along the squares' edges.
    for (const Switches& run : {Switches(), Switches({"-A10,1"}), Switches({"-A5,0.5"}),
                                Switches({"-Db"}), Switches({"-Da"})}) {
        EXPECT_EQ(check_emission_and_ambient(s, run), 24) << run.name();
    }
    // With lghtick 2 the emitters are lights too, but no weight d or s reflects them; nor with -Ds.
    ProbeScene lit = quadrants();
    lit.lghtick = 2;
    for (const Switches& run : {Switches(), Switches({"-Ds"})}) {
        EXPECT_EQ(check_emission_and_ambient(lit, run), 24) << "lghtick 2, " << run.name();
    }
}

TEST(PixelProbes, EmissionAndAmbientLightSeenObliquely) {
    ProbeScene s = quadrants();
    s.eye = {7.0, 9.0, -22.0};
    s.look = {2.0, -1.0, 5.0};
    s.width = 9;
    s.height = 7;
    EXPECT_GE(check_emission_and_ambient(s, Switches({"-A10,1"})), 60);
}

// ---- A square lit by one emitter ----

constexpr int kTarget = 0;
constexpr int kLight = 1;
constexpr int kBlocker = 2;

// A 20 x 20 square facing the eye at z = 0, lit by a small emissive square (side 1) up and to the
// right, off the screen, facing the eye (its back to the target) unless turned. With `shine`, the
// target has a Phong highlight of that weight.
ProbeScene lit_square(int lghtick, double shine = 0.0, double light_turn_degrees = 0.0) {
    ProbeScene s;
    s.lghtick = lghtick;
    s.attributes = {{.colour = {0.9, 0.6, 0.3}, .a = 0.1, .d = 0.7, .s = shine, .pow = 8.0},
                    {.colour = {1.0, 0.9, 0.8}, .e = 1.5}};
    s.squares = {{kTarget, 10.0, {0.0, 0.0, 0.0}},
                 {kLight, 0.5, {6.0, 8.0, -10.0}, light_turn_degrees}};
    return s;
}

// The lit square with a square of side 2 halfway to the light, which shades the middle pixel.
ProbeScene shadowed_square(int lghtick, const ProbeAttribute& blocker) {
    ProbeScene s = lit_square(lghtick);
    s.attributes.push_back(blocker);
    s.squares.push_back({kBlocker, 1.0, {3.0, 4.0, -5.0}});
    return s;
}

struct PointLight {
    V position;
    Colour intensity;
    V emitter_normal;  ///< the outward normal of the emissive square
};

// The emitter's point sources (manual 2.2, docs/rendering.md): lghtick 2, its centre; lghtick 1,
// its corners. One light of intensity C·e, shared equally among its points.
std::vector<PointLight> point_lights(const ProbeScene& s) {
    const Placed light = place(s.squares[kLight]);
    const ProbeAttribute& a = s.attributes[kLight];
    const Colour total = colour_of(a) * a.e;
    if (s.lghtick == 2) {
        return {{light.centre, total, light.normal}};
    }
    std::vector<PointLight> corners;
    for (const double i : {-1.0, 1.0}) {
        for (const double j : {-1.0, 1.0}) {
            corners.push_back(
                {light.centre + light.u * i + light.v * j, total * 0.25, light.normal});
        }
    }
    return corners;
}

struct Probed {
    int pixels = 0;
    int shadowed = 0;  ///< pixels with a feeler through the blocker
};

// What a feeler brings through square `blocker` (or kNoSquare): all of it, t·C of a transparent
// one (unless -Dt), nothing through an opaque one.
Colour feeler_filter(const ProbeScene& s, const Switches& run, int blocker) {
    if (blocker == kNoSquare) {
        return {1.0, 1.0, 1.0};
    }
    const ProbeSquare& q = s.squares[static_cast<std::size_t>(blocker)];
    const ProbeAttribute& b = s.attributes[static_cast<std::size_t>(q.attribute)];
    return b.t > 0.0 && run.feelers_pass_glass ? colour_of(b) * b.t : Colour{};
}

// The light one point source adds at a point of normal N seen from V: d·C·cosθ + s·cos^pow α
// (Phong, the highlight in the light's colour), times what reaches the point.
Colour light_from(const ProbeAttribute& a, V normal, V view, V to_light, Colour received) {
    const double cos_theta = dot(normal, to_light);
    EXPECT_GT(cos_theta, 0.0) << "the light is on the viewer's side";
    Colour added = colour_of(a) * received * (a.d * cos_theta);
    if (a.s > 0.0) {
        const V mirrored = normal * (2.0 * cos_theta) - to_light;  // R = 2(N·L)N - L
        const double cos_alpha = dot(mirrored, view);
        added = added + received * (cos_alpha > 0.0 ? a.s * std::pow(cos_alpha, a.pow) : 0.0);
    }
    return added;
}

// Every pixel that sees the target: a·C plus each point light's share, the light's intensity
// attenuated along the feeler and filtered by a blocker; all times the eye ray's attenuation.
// Pixels whose feelers graze the blocker's edge are left out, and with a highlight those whose
// mirror ray meets anything (it must bring black).
Probed check_lit_target(const ProbeScene& s, const Switches& run) {
    const TempDir dir;
    const GroPixels gro = render_probe(dir, s, run.words);
    const ProbeAttribute& a = s.attributes[kTarget];
    const V normal = place(s.squares[kTarget]).normal;  // faces the eye
    Probed probed;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const Ray ray = pixel_ray(s, x, y);
            const FirstHit hit = first_hit(s, ray);
            if (hit.square != kTarget || !hit.clear) {
                continue;
            }
            const V point = hit.at.point;
            const V view = ray.direction * -1.0;
            const Ray mirror{point, ray.direction - normal * (2.0 * dot(ray.direction, normal))};
            const FirstHit mirrored = first_hit(s, mirror, kTarget);
            bool callable = a.s == 0.0 || (mirrored.square == kNoSquare && mirrored.clear);
            bool shadowed = false;
            Colour want = colour_of(a) * a.a;
            for (const PointLight& light : point_lights(s)) {
                const int blocker = feeler_blocker(s, point, light.position, kLight, kTarget);
                callable = callable && blocker != kTooCloseToCall;
                shadowed = shadowed || (blocker != kNoSquare && blocker != kTooCloseToCall);
                const V span = light.position - point;
                if (!run.back_emits && dot(span, light.emitter_normal) >= 0.0) {
                    continue;  // -Db: the point is behind the emitter, which emits outward only
                }
                const Colour received = light.intensity * feeler_filter(s, run, blocker) *
                                        feeler_factor(run, length(span));
                want = want + light_from(a, normal, view, unit(span), received);
            }
            if (!callable) {
                continue;
            }
            expect_pixel(gro, x, y, want * ray_factor(run, hit.at.t), run.name());
            ++probed.pixels;
            probed.shadowed += shadowed ? 1 : 0;
        }
    }
    return probed;
}

TEST(PixelProbes, PointLitByOneEmitterWithAttenuation) {
    const ProbeScene s = lit_square(2);
    // Every pixel sees the target.
    for (const Switches& run : {Switches(), Switches({"-A20,0.5"}), Switches({"-Da"}),
                                Switches({"-Dl"}), Switches({"-Da", "-Dl", "-A20,0.5"})}) {
        EXPECT_EQ(check_lit_target(s, run).pixels, 35) << run.name();
    }
}

TEST(PixelProbes, LghtickOneLightsFromTheCornersWithAQuarterEach) {
    SCOPED_TRACE("lghtick 1");
    EXPECT_EQ(check_lit_target(lit_square(1), Switches()).pixels, 35);
    EXPECT_EQ(check_lit_target(lit_square(1), Switches({"-A20,0.5"})).pixels, 35);
}

TEST(PixelProbes, PhongHighlightOfOneEmitter) {
    EXPECT_EQ(check_lit_target(lit_square(2, 0.3), Switches()).pixels, 35);
}

// -Db: "only the 'outside' surface of emissive polygons emits light" (manual Appendix), so a
// point behind a one-sided emitter gets none of its light, as it sees none of its emission.
TEST(PixelProbes, OneSidedEmitterLightsOnlyWhatItFaces) {
    for (const int lghtick : {2, 1}) {
        SCOPED_TRACE("lghtick " + std::to_string(lghtick));
        EXPECT_EQ(check_lit_target(lit_square(lghtick, 0.0, 0.0), Switches({"-Db"})).pixels, 35);
        EXPECT_EQ(check_lit_target(lit_square(lghtick, 0.0, 180.0), Switches({"-Db"})).pixels, 35);
        EXPECT_EQ(check_lit_target(lit_square(lghtick, 0.0, 180.0), Switches()).pixels, 35);
    }
}

// ---- Shadows ----

const ProbeAttribute opaque_grey{.colour = {0.5, 0.5, 0.5}, .a = 0.3};
const ProbeAttribute blue_glass{.colour = {0.5, 0.8, 1.0}, .a = 0.1, .t = 0.6};

TEST(PixelProbes, ShadowBehindAnOpaqueBlockerIsAmbientOnly) {
    for (const int lghtick : {2, 1}) {
        SCOPED_TRACE("lghtick " + std::to_string(lghtick));
        const Probed p = check_lit_target(shadowed_square(lghtick, opaque_grey), Switches());
        EXPECT_GE(p.shadowed, 1);
        EXPECT_GE(p.pixels, 30);
    }
}

TEST(PixelProbes, ShadowBehindATransparentBlockerIsFilteredByItsColour) {
    const ProbeScene s = shadowed_square(2, blue_glass);
    for (const Switches& run : {Switches(), Switches({"-A20,0.5"}), Switches({"-Dt"})}) {
        const Probed p = check_lit_target(s, run);
        EXPECT_GE(p.shadowed, 1) << run.name();
        EXPECT_GE(p.pixels, 30) << run.name();
    }
    SCOPED_TRACE("lghtick 1");
    const Probed corners = check_lit_target(shadowed_square(1, blue_glass), Switches());
    EXPECT_GE(corners.shadowed, 1);
}

}  // namespace
}  // namespace rt::test::probe
