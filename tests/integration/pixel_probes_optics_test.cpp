// Pixel probes, optics and display: a mirror reflecting a flat colour (s·I), a pane of glass in
// front of one (t·C·I, Snell's law), and the display mapping of -m and -c, computed here from the
// manual's formulas and docs/rendering.md against what the real rt program writes.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "integration/pixel_probes.h"
#include "support/hand_readers.h"
#include "support/probe_scene.h"
#include "support/temp_dir.h"

namespace rt::test::probe {
namespace {

// What a polygon sends back by itself with no lights and no diffuse weight: e·C (from both sides
// unless -Db) and a·C.
Colour own_light(const ProbeScene& s, int square, const Ray& ray, const Switches& run) {
    const ProbeSquare& q = s.squares[static_cast<std::size_t>(square)];
    const ProbeAttribute& a = s.attributes[static_cast<std::size_t>(q.attribute)];
    const bool front = dot(ray.direction, place(q).normal) < 0.0;
    return colour_of(a) * ((front || run.back_emits ? a.e : 0.0) + a.a);
}

// What a secondary ray from square `leaving` brings: the own light of the square it meets,
// attenuated over the distance (black if it meets none). Unset if an edge is too close to call.
std::optional<Colour> flat_seen(const ProbeScene& s, const Ray& ray, int leaving,
                                const Switches& run) {
    const FirstHit hit = first_hit(s, ray, leaving);
    if (!hit.clear) {
        return std::nullopt;
    }
    if (hit.square == kNoSquare) {
        return Colour{};
    }
    return own_light(s, hit.square, ray, run) * ray_factor(run, hit.at.t);
}

// ---- A mirror ----

constexpr int kMirror = 0;
constexpr int kFlat = 1;
constexpr int kPane = 0;
constexpr int kBack = 1;

// A mirror (s = 0.8, no diffuse weight, a sharp cone) turned 45 degrees about y at the origin,
// so that the middle pixel's ray turns to -x, where an emissive square faces it. No lights.
ProbeScene mirror_scene(int maxdepth = 3) {
    ProbeScene s;
    s.maxdepth = maxdepth;
    s.attributes = {{.colour = {0.9, 0.85, 0.8}, .a = 0.05, .s = 0.8},
                    {.colour = {0.2, 0.7, 0.4}, .e = 0.9}};
    s.squares = {{kMirror, 6.0, {0.0, 0.0, 0.0}, 45.0}, {kFlat, 5.0, {-10.0, 0.0, 0.0}, -90.0}};
    return s;
}

// Every pixel that sees the mirror: (a·C + s·I(reflected)) times the eye ray's attenuation, I
// attenuated over the reflected ray's length. Returns how many of them see the flat square.
int check_mirror(const ProbeScene& s, const Switches& run, bool reflects) {
    const TempDir dir;
    const GroPixels gro = render_probe(dir, s, run.words);
    const ProbeAttribute& m = s.attributes[kMirror];
    int reflections = 0;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const Ray ray = pixel_ray(s, x, y);
            const FirstHit hit = first_hit(s, ray);
            if (hit.square != kMirror || !hit.clear) {
                continue;
            }
            const V n = place(s.squares[kMirror]).normal;
            const Ray reflected{hit.at.point, ray.direction - n * (2.0 * dot(ray.direction, n))};
            const std::optional<Colour> seen = flat_seen(s, reflected, kMirror, run);
            if (!seen) {
                continue;
            }
            const Colour local = colour_of(m) * m.a;
            const Colour want = reflects ? local + *seen * m.s : local;
            expect_pixel(gro, x, y, want * ray_factor(run, hit.at.t), run.name());
            reflections += first_hit(s, reflected, kMirror).square == kFlat ? 1 : 0;
        }
    }
    return reflections;
}

TEST(PixelProbes, MirrorReflectingAFlatColour) {
    const ProbeScene s = mirror_scene();
    const Ray middle = pixel_ray(s, 3, 2);
    ASSERT_EQ(first_hit(s, middle).square, kMirror);
    for (const Switches& run : {Switches(), Switches({"-A10,1"}), Switches({"-Da"})}) {
        EXPECT_GE(check_mirror(s, run, true), 9) << run.name();
    }
}

TEST(PixelProbes, MirrorWithoutReflectedRays) {
    EXPECT_GE(check_mirror(mirror_scene(), Switches({"-Dr"}), false), 9);
    SCOPED_TRACE("maxdepth 1");
    EXPECT_GE(check_mirror(mirror_scene(1), Switches(), false), 9);
}

// ---- A pane of glass ----

// A pane (t = 0.8, index 1.5, a little ambient) at z = 0 facing the eye, a flat ambient-only
// square behind it at z = 6. No lights.
ProbeScene glass_scene(int maxdepth = 3) {
    ProbeScene s;
    s.maxdepth = maxdepth;
    s.attributes = {{.colour = {0.7, 0.9, 0.8}, .a = 0.05, .t = 0.8, .refraction_index = 1.5},
                    {.colour = {0.9, 0.3, 0.2}, .a = 0.6}};
    s.squares = {{kPane, 4.0, {0.0, 0.0, 0.0}}, {kBack, 30.0, {0.0, 0.0, 6.0}}};
    return s;
}

// Snell's law from air into index n: the refracted direction of a unit `d` meeting a surface of
// unit normal `n` facing it (d·n < 0).
V refract_into(V d, V n, double index) {
    const double eta = 1.0 / index;
    const double cos_i = -dot(d, n);
    const double cos_t = std::sqrt(1.0 - eta * eta * (1.0 - cos_i * cos_i));
    return d * eta + n * (eta * cos_i - cos_t);
}

// Every pixel: through the pane, (a·C + t·C·I(refracted)) times the eye ray's attenuation; past
// it, the back square's a·C attenuated. Returns how many pixels look through the pane.
int check_glass(const ProbeScene& s, const Switches& run, bool transmits) {
    const TempDir dir;
    const GroPixels gro = render_probe(dir, s, run.words);
    const ProbeAttribute& g = s.attributes[kPane];
    int through = 0;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const Ray ray = pixel_ray(s, x, y);
            const FirstHit hit = first_hit(s, ray);
            if (!hit.clear || hit.square == kNoSquare) {
                continue;
            }
            if (hit.square == kBack) {
                expect_pixel(gro, x, y, own_light(s, kBack, ray, run) * ray_factor(run, hit.at.t),
                             run.name() + ", past the pane");
                continue;
            }
            const V n = place(s.squares[kPane]).normal;  // faces the eye
            const Ray refracted{hit.at.point, refract_into(ray.direction, n, g.refraction_index)};
            const std::optional<Colour> seen = flat_seen(s, refracted, kPane, run);
            if (!seen) {
                continue;
            }
            Colour want = colour_of(g) * g.a;
            if (transmits) {
                want = want + colour_of(g) * *seen * g.t;
            }
            expect_pixel(gro, x, y, want * ray_factor(run, hit.at.t), run.name() + ", through");
            ++through;
        }
    }
    return through;
}

TEST(PixelProbes, ColourSeenStraightThroughAPaneOfGlass) {
    const ProbeScene s = glass_scene();
    // The middle pixel meets the pane at normal incidence: its ray goes on unbent.
    const Ray middle = pixel_ray(s, 3, 2);
    ASSERT_EQ(first_hit(s, middle).square, kPane);
    const V bent = refract_into(middle.direction, place(s.squares[kPane]).normal, 1.5);
    EXPECT_NEAR(length(bent - middle.direction), 0.0, 1e-15);
    // The others meet it obliquely and are bent by Snell's law, which -A10,1 makes visible: the
    // path to the back square is shorter than unbent.
    for (const Switches& run : {Switches(), Switches({"-A10,1"}), Switches({"-Da"})}) {
        EXPECT_GE(check_glass(s, run, true), 9) << run.name();
    }
}

TEST(PixelProbes, PaneOfGlassAtMaxdepthOneShowsOnlyItsOwnLight) {
    EXPECT_GE(check_glass(glass_scene(1), Switches(), false), 9);
}

// ---- Display mapping ----

// The manual's Appendix -m and -c: display value = intensity · 255 · m; a pixel whose largest
// value exceeds 255 is scaled down in proportion (clipping on), or with -c each value wraps modulo
// 256. Values are rounded to the nearest level.
std::array<int, 3> display_levels(Colour intensity, double m, bool clip) {
    std::array<double, 3> v{intensity.r * 255.0 * m, intensity.g * 255.0 * m,
                            intensity.b * 255.0 * m};
    const double largest = std::max({v[0], v[1], v[2]});
    if (clip && largest > 255.0) {
        for (double& value : v) {
            value *= 255.0 / largest;
        }
    }
    std::array<int, 3> levels{};
    for (std::size_t c = 0; c < 3; ++c) {
        // Chosen intensities stay clear of rounding ties, so any correct arithmetic agrees.
        EXPECT_GT(std::fabs(v[c] - std::floor(v[c]) - 0.5), 0.05) << "too close to a tie";
        const int rounded = static_cast<int>(std::lround(v[c]));
        levels[c] = clip ? rounded : rounded % 256;
    }
    return levels;
}

TEST(PixelProbes, DisplayMappingMultipliesClipsAndWraps) {
    // A square emitting e·C = (0.72, 0.4, 0.24) fills the view; -Da keeps it exact.
    ProbeScene s;
    s.attributes = {{.colour = {0.9, 0.5, 0.3}, .e = 0.8}};
    s.squares = {{0, 30.0, {0.0, 0.0, 0.0}}};
    const Colour emitted{0.72, 0.4, 0.24};
    struct Case {
        std::vector<std::string> switches;
        std::string multiplier;  ///< as the .gro header writes it
        bool clip;
        std::array<int, 3> by_hand;  ///< worked out on paper, as a check on display_levels
    };
    for (const Case& c :
         {Case{{}, "1", true, {184, 102, 61}}, Case{{"-m0.5"}, "0.5", true, {92, 51, 31}},
          Case{{"-m2"}, "2", true, {255, 142, 85}},
          Case{{"-m2", "-c"}, "2", false, {111, 204, 122}},
          Case{{"-m3", "-c"}, "3", false, {39, 50, 184}}}) {
        std::vector<std::string> switches = c.switches;
        switches.insert(switches.end(), {"-Da", "--output", "probe.ppm"});
        const std::string name = "-m" + c.multiplier + (c.clip ? "" : " -c");
        const TempDir dir;
        const GroPixels gro = render_probe(dir, s, switches);
        const std::array<int, 3> want = display_levels(emitted, std::stod(c.multiplier), c.clip);
        EXPECT_EQ(want, c.by_hand) << name;
        EXPECT_EQ(gro.header.at("display_multiplier"), c.multiplier) << name;
        EXPECT_EQ(gro.header.at("display_clip"), c.clip ? "on" : "off") << name;
        const Image8 ppm = parse_ppm(read_text(dir.path() / "probe.ppm"));
        ASSERT_EQ(ppm.width, s.width);
        ASSERT_EQ(ppm.height, s.height);
        for (int y = 0; y < s.height; ++y) {
            for (int x = 0; x < s.width; ++x) {
                // The .gro keeps the linear intensity whatever -m and -c.
                expect_pixel(gro, x, y, emitted, name);
                const std::size_t i = static_cast<std::size_t>(y * s.width + x) * 3;
                EXPECT_EQ((std::array<int, 3>{ppm.rgb[i], ppm.rgb[i + 1], ppm.rgb[i + 2]}), want)
                    << name << ": pixel (" << x << ", " << y << ")";
            }
        }
    }
}

}  // namespace
}  // namespace rt::test::probe
