// The step from the parsed command line to the library's settings (run_settings.h,
// make_accelerator.h's method_for_scene), switch by switch. Each row gives a command line and
// exactly the settings it must change from the defaults: a switch that is dropped changes nothing
// and fails its row; a switch wired to the wrong setting changes another one and fails it too.
#include "rt/app/run_settings.h"

#include <map>
#include <string>
#include <vector>

#include "rt/accel/make_accelerator.h"
#include "rt/app/switch_parser.h"
#include "rt/core/error.h"
#include "rt/render/film_window.h"
#include "rt/shading/lights.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

using Fields = std::map<std::string, std::string>;

std::string text(bool value) {
    return value ? "true" : "false";
}
std::string text(double value) {
    return fmt::format("{}", value);
}

std::string law_name(SpecularLaw law) {
    switch (law) {
        case SpecularLaw::Phong:
            return "Phong";
        case SpecularLaw::PhongGeometric:
            return "PhongGeometric";
        case SpecularLaw::TorranceSparrowGaussian:
            return "TorranceSparrowGaussian";
        case SpecularLaw::TorranceSparrowBeckmann:
            return "TorranceSparrowBeckmann";
    }
    return "?";
}

std::string tint_name(HighlightTint tint) {
    switch (tint) {
        case HighlightTint::LightColor:
            return "LightColor";
        case HighlightTint::ObjectColor:
            return "ObjectColor";
        case HighlightTint::Fresnel:
            return "Fresnel";
    }
    return "?";
}

std::string warn_name(WarnMode mode) {
    switch (mode) {
        case WarnMode::None:
            return "None";
        case WarnMode::Rogers:
            return "Rogers";
        case WarnMode::Conical:
            return "Conical";
        case WarnMode::Thibadeau:
            return "Thibadeau";
    }
    return "?";
}

// Every field of the shading settings, by name. The Gaussian normaliser is derived from the
// slope and checked on its own below.
Fields describe(const ShadingSettings& s) {
    const SamplingSettings& x = s.sampling;
    return {
        {"attenuation_distance", text(s.attenuation_distance)},
        {"attenuation_constant", text(s.attenuation_constant)},
        {"attenuate_rays", text(s.attenuate_rays)},
        {"attenuate_feelers", text(s.attenuate_feelers)},
        {"shadow_feelers", text(s.shadow_feelers)},
        {"feelers_stop_at_transparent", text(s.feelers_stop_at_transparent)},
        {"reflection", text(s.reflection)},
        {"both_sides_emit", text(s.both_sides_emit)},
        {"far_side_feelers", text(s.far_side_feelers)},
        {"smooth_shaded_opaque", text(s.smooth_shaded_opaque)},
        {"ambient_light", text(s.ambient_light)},
        {"seed", std::to_string(x.seed)},
        {"distribute", text(x.distribute)},
        {"adaptive", text(x.adaptive)},
        {"pixel_stop.probability", text(x.pixel_stop.probability)},
        {"pixel_stop.variance", text(x.pixel_stop.variance)},
        {"ray_stop.probability", text(x.ray_stop.probability)},
        {"ray_stop.variance", text(x.ray_stop.variance)},
        {"illuminate_distributed", text(x.illuminate_distributed)},
        {"fuzzy.angle", text(s.fuzzy.angle)},
        {"fuzzy.count", std::to_string(s.fuzzy.count)},
        {"specular.law()", law_name(s.specular.law())},
        {"specular.slope_m()", text(s.specular.slope_m())},
        {"specular.tint", tint_name(s.specular.tint)},
        {"warn.mode", warn_name(s.warn.mode)},
        {"warn.cone_angle", text(s.warn.cone_angle)},
        {"warn.displacement", text(s.warn.displacement)},
        {"correct_smoothing", text(s.correct_smoothing)},
        {"share_light_among_points", text(s.share_light_among_points)},
    };
}

// The fields of `got` that differ from `base`, with got's values.
Fields changes(const Fields& base, const Fields& got) {
    Fields changed;
    for (const auto& [name, value] : got) {
        if (base.at(name) != value) {
            changed[name] = value;
        }
    }
    return changed;
}

ShadingSettings shading_for(std::vector<std::string> switches) {
    switches.insert(switches.begin(), "scene");
    return run_shading(parse_command_line(switches));
}

struct ShadingRow {
    std::vector<std::string> switches;
    Fields expected;  ///< exactly the fields that change, and their values
};

const std::vector<ShadingRow>& shading_rows() {
    static const std::vector<ShadingRow> rows{
        {{"-A40.0,0.5"}, {{"attenuation_distance", "40"}, {"attenuation_constant", "0.5"}}},
        {{"-Da"}, {{"attenuate_rays", "false"}}},
        {{"-Dl"}, {{"attenuate_feelers", "false"}}},
        {{"-DI"}, {{"attenuate_feelers", "false"}}},
        {{"-Ds"}, {{"shadow_feelers", "false"}}},
        {{"-Dt"}, {{"feelers_stop_at_transparent", "true"}}},
        {{"-Dr"}, {{"reflection", "false"}}},
        {{"-Db"}, {{"both_sides_emit", "false"}}},
        {{"-T"}, {{"far_side_feelers", "true"}}},
        {{"-Po"}, {{"smooth_shaded_opaque", "true"}}},
        {{"-Pt"}, {}},
        {{"--seed", "7"}, {{"seed", "7"}}},
        {{"-Dd"}, {{"distribute", "false"}}},
        {{"-Dx"}, {{"adaptive", "false"}}},
        {{"-Xp0.1,0.05"}, {{"pixel_stop.probability", "0.1"}, {"pixel_stop.variance", "0.05"}}},
        {{"-Xr0.3,0.07"}, {{"ray_stop.probability", "0.3"}, {"ray_stop.variance", "0.07"}}},
        {{"-I"}, {{"illuminate_distributed", "true"}}},
        {{"-F0.3,2.0"}, {{"fuzzy.angle", "0.3"}, {"fuzzy.count", "2"}}},
        {{"-F0.05,2.5"}, {{"fuzzy.angle", "0.05"}, {"fuzzy.count", "3"}}},
        {{"-Sp"}, {}},
        {{"-Sg"}, {{"specular.law()", "PhongGeometric"}}},
        {{"-Stg0.3"},
         {{"specular.law()", "TorranceSparrowGaussian"}, {"specular.slope_m()", "0.3"}}},
        {{"-Stb0.4"},
         {{"specular.law()", "TorranceSparrowBeckmann"}, {"specular.slope_m()", "0.4"}}},
        {{"-Ci"}, {}},
        {{"-Co"}, {{"specular.tint", "ObjectColor"}}},
        {{"-Cf"}, {{"specular.tint", "Fresnel"}}},
        {{"-Wr"}, {{"warn.mode", "Rogers"}}},
        {{"-Wc", "0.7"}, {{"warn.mode", "Conical"}, {"warn.cone_angle", "0.7"}}},
        {{"-Wt1.5"}, {{"warn.mode", "Thibadeau"}, {"warn.displacement", "1.5"}}},
        {{"-Ot"}, {{"correct_smoothing", "false"}}},
        // -Oi: the earliest version (docs/rendering.md): no attenuation, feelers stopping at
        // every polygon, no -T, no distribution, no fuzzy feelers, unshared point sources.
        {{"-Oi", "-T", "-F0.3,2"},
         {{"attenuate_rays", "false"},
          {"attenuate_feelers", "false"},
          {"feelers_stop_at_transparent", "true"},
          {"distribute", "false"},
          {"share_light_among_points", "false"}}},
        {{"-O1"},
         {{"attenuate_rays", "false"},
          {"attenuate_feelers", "false"},
          {"feelers_stop_at_transparent", "true"},
          {"distribute", "false"},
          {"adaptive", "false"},
          {"share_light_among_points", "false"}}},
    };
    return rows;
}

TEST(ShadingSettingsFromSwitches, EachSwitchChangesExactlyItsSettings) {
    const Fields defaults = describe(shading_for({}));
    for (const ShadingRow& row : shading_rows()) {
        const std::string line = fmt::format("{}", fmt::join(row.switches, " "));
        EXPECT_EQ(changes(defaults, describe(shading_for(row.switches))), row.expected) << line;
    }
}

TEST(ShadingSettingsFromSwitches, DefaultsAreTheManuals) {
    const Fields d = describe(shading_for({}));
    // -A: "By default, attenuation is turned on, with parameters 200.0 and 1.0."
    EXPECT_EQ(d.at("attenuation_distance"), "200");
    EXPECT_EQ(d.at("attenuation_constant"), "1");
    // -X: "The defaults for the maximum variance and the probability are all 0.2."
    EXPECT_EQ(d.at("pixel_stop.probability"), "0.2");
    EXPECT_EQ(d.at("pixel_stop.variance"), "0.2");
    EXPECT_EQ(d.at("ray_stop.probability"), "0.2");
    EXPECT_EQ(d.at("ray_stop.variance"), "0.2");
    // -S: "The default is Phong." -I and -T are off by default (manual part four).
    EXPECT_EQ(d.at("specular.law()"), "Phong");
    EXPECT_EQ(d.at("illuminate_distributed"), "false");
    EXPECT_EQ(d.at("far_side_feelers"), "false");
    EXPECT_EQ(d.at("both_sides_emit"), "true");
    EXPECT_EQ(d.at("attenuate_rays"), "true");
    EXPECT_EQ(d.at("attenuate_feelers"), "true");
}

TEST(ShadingSettingsFromSwitches, GaussianNormaliserFollowsTheSlope) {
    // c(m) -> 1/(pi m^2) for small m (docs/illumination-models.md).
    const double m = 0.05;
    const ShadingSettings s = shading_for({"-Stg0.05"});
    EXPECT_NEAR(s.specular.gaussian_normaliser() * 3.141592653589793 * m * m, 1.0, 0.01);
    const ShadingSettings wide = shading_for({"-Stg0.5"});
    EXPECT_LT(wide.specular.gaussian_normaliser(), s.specular.gaussian_normaliser() / 10.0);
}

// --- the film window (-L) --------------------------------------------------------------------

Scene scene_with_window(int left, int top, int right, int bottom) {
    Scene scene = test::SceneBuilder().scene();
    scene.view.window = {left, top, right, bottom};
    return scene;
}

PixelRect window_for(const Scene& scene, std::vector<std::string> switches) {
    switches.insert(switches.begin(), "scene");
    return film_window(scene.view.window, parse_command_line(switches).start_line);
}

TEST(RenderWindowFromSwitches, IsTheOutputMatrixCutAtL) {
    const Scene scene = scene_with_window(10, 20, 109, 99);
    EXPECT_EQ(window_for(scene, {}), (PixelRect{10, 20, 109, 99}));
    // -L50: "draws only from line 50 up": rows 50, 49, ..., 20.
    EXPECT_EQ(window_for(scene, {"-L50"}), (PixelRect{10, 20, 109, 50}));
    EXPECT_EQ(window_for(scene, {"-L", "20"}), (PixelRect{10, 20, 109, 20}));
    // A line below the window's bottom leaves the window whole.
    EXPECT_EQ(window_for(scene, {"-L500"}), (PixelRect{10, 20, 109, 99}));
    EXPECT_THROW(window_for(scene, {"-L19"}), SettingError);
}

// --- what the switches change in the scene (-E, -K) ----------------------------------------

// A lit floor: an emissive square above a square of a given attribute.
Scene lit_scene(const Attribute& floor) {
    test::SceneBuilder b;
    Scene& scene = b.scene();
    Attribute light;
    light.color = {1.0, 1.0, 1.0};
    light.emission = 2.0;  // one light of intensity 2 (lghtick 2: at its centre)
    scene.attributes = {floor, light};
    b.add_polygon({{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}}, {0, 1, 0}, 0);
    b.add_polygon({{-1, 5, -1}, {1, 5, -1}, {1, 5, 1}, {-1, 5, 1}}, {0, -1, 0}, 1);
    scene.header.lghtick = 2;
    return scene;
}

Attribute glossy_attribute() {
    Attribute a;
    a.color = {0.9, 0.9, 0.9};
    a.ambient = 0.1;
    a.diffuse = 0.5;
    a.specular = 0.6;
    return a;
}

Attribute prepared_floor(Scene scene, std::vector<std::string> switches) {
    switches.insert(switches.begin(), "scene");
    const Options options = parse_command_line(switches);
    prepare_scene(scene, options, run_shading(options));
    return scene.attributes[0];
}

TEST(PrepareSceneFromSwitches, KScalesTheWeightsByTheBound) {
    // docs/illumination-models.md: bound = e + a A + d D + s L + s' + t, with one light of
    // intensity L = 2, ambient A = 1, attenuation constant c = 1.
    const Scene scene = lit_scene(glossy_attribute());
    EXPECT_EQ(prepared_floor(scene, {}).specular, 0.6);  // not without -K
    const double bound = 0.1 + 0.5 * 2 + 0.6 * 2 + 0.6;
    const Attribute k = prepared_floor(scene, {"-K"});
    EXPECT_DOUBLE_EQ(k.specular, 0.6 / bound);
    EXPECT_DOUBLE_EQ(k.ambient, 0.1 / bound);
    EXPECT_DOUBLE_EQ(k.diffuse, 0.5 / bound);
    // -K looks at -Dr: no mirrored ray (s' = 0).
    EXPECT_DOUBLE_EQ(prepared_floor(scene, {"-K", "-Dr"}).specular, 0.6 / (bound - 0.6));
    // ... and at -Ds: no feelers, so no highlight (L = 0), and diffuse rays bring at most 1.
    EXPECT_DOUBLE_EQ(prepared_floor(scene, {"-K", "-Ds"}).specular, 0.6 / (0.1 + 0.5 + 0.6));
    // Both: the bound 0.6 is under 1, nothing is scaled.
    EXPECT_DOUBLE_EQ(prepared_floor(scene, {"-K", "-Ds", "-Dr"}).specular, 0.6);
    // A smaller attenuation constant raises what a light can deliver: L = 2 / 0.5.
    const double near_bound = 0.1 + 0.5 * 4 + 0.6 * 4 + 0.6;
    EXPECT_DOUBLE_EQ(prepared_floor(scene, {"-K", "-A200,0.5"}).specular, 0.6 / near_bound);
    // ... unless feelers are not attenuated (-Dl).
    EXPECT_DOUBLE_EQ(prepared_floor(scene, {"-K", "-A200,0.5", "-Dl"}).specular, 0.6 / bound);
}

TEST(PrepareSceneFromSwitches, ECreasesSmoothNormals) {
    // A smooth-shaded cube: without -E a corner's normal averages three faces; with -E1.0 each
    // face keeps its own normal at its corners.
    Scene cube = test::make_box({0, 0, 0}, {1, 1, 1}, false);
    for (Polygon& p : cube.polygons) {
        p.smooth = true;
    }
    const auto corner_normals = [](Scene scene, std::vector<std::string> switches) {
        switches.insert(switches.begin(), "scene");
        const Options options = parse_command_line(switches);
        prepare_scene(scene, options, run_shading(options));
        return scene;
    };
    EXPECT_TRUE(corner_normals(cube, {}).corner_normals.empty());
    const Scene creased = corner_normals(cube, {"-E1.0"});
    ASSERT_EQ(creased.corner_normals.size(), creased.corners.size());
    for (const Polygon& p : creased.polygons) {
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const Vec3 n = creased.corner_normals[p.first_corner + k];
            EXPECT_NEAR(dot(n, p.normal), 1.0, 1e-12);
        }
    }
    // With an angle wider than the cube's edges (pi/2), a corner's normal leans off each face.
    const Scene blunt = corner_normals(cube, {"-E1.6"});
    ASSERT_EQ(blunt.corner_normals.size(), blunt.corners.size());
    const Polygon& face = blunt.polygons[0];
    EXPECT_LT(dot(blunt.corner_normals[face.first_corner], face.normal), 0.99);
}

// --- the intersection method (-od -ol -ss -op -on -of -tv --accel --threads) -----------------

AccelSettings accel_for(const SceneHeader& header, std::vector<std::string> switches) {
    Scene scene = test::SceneBuilder().scene();
    scene.header = header;
    switches.insert(switches.begin(), "scene");
    return method_for_scene(scene, run_accelerator_stack(parse_command_line(switches)).method);
}

TEST(AccelSettingsFromSwitches, HeaderChoosesAndSwitchesOverride) {
    SceneHeader octree;
    octree.sptncde = 1;
    octree.octr = 4;
    EXPECT_EQ(accel_for(octree, {}).kind, AccelKind::Octree);
    EXPECT_EQ(accel_for(octree, {}).octree.depth, 4);
    EXPECT_EQ(accel_for(octree, {"-od6"}).octree.depth, 6);
    SceneHeader seads;
    seads.sptncde = 12;
    EXPECT_EQ(accel_for(seads, {}).kind, AccelKind::Seads);
    EXPECT_EQ(accel_for(seads, {}).seads_resolution, 12);
    EXPECT_EQ(accel_for(SceneHeader{}, {}).kind, AccelKind::BruteForce);
    EXPECT_EQ(accel_for(octree, {"--accel", "bvh"}).kind, AccelKind::Bvh);
    EXPECT_EQ(accel_for(octree, {"--accel", "brute"}).kind, AccelKind::BruteForce);
    EXPECT_EQ(accel_for(SceneHeader{}, {"--accel", "seads"}).kind, AccelKind::Seads);
    EXPECT_THROW(accel_for(octree, {"--accel", "kd"}), UsageError);
}

TEST(AccelSettingsFromSwitches, EachOctreeSwitchSetsItsField) {
    SceneHeader octree;
    octree.sptncde = 1;
    octree.octr = 4;
    const AccelSettings base = accel_for(octree, {});
    EXPECT_FALSE(base.octree.octlist_power || base.octree.seed_size_power ||
                 base.terminate_after_voxels);
    EXPECT_FALSE(base.octree.level_order || base.accept_near_hits || base.no_fudge);
    EXPECT_EQ(accel_for(octree, {"-ol16"}).octree.octlist_power, 16);
    EXPECT_EQ(accel_for(octree, {"-ss10"}).octree.seed_size_power, 10);
    EXPECT_EQ(accel_for(octree, {"-tv8"}).terminate_after_voxels, 8);
    const AccelSettings op = accel_for(octree, {"-op"});
    EXPECT_TRUE(op.octree.level_order && !op.accept_near_hits && !op.no_fudge);
    const AccelSettings on = accel_for(octree, {"-on"});
    EXPECT_TRUE(!on.octree.level_order && on.accept_near_hits && !on.no_fudge);
    const AccelSettings of = accel_for(octree, {"-of"});
    EXPECT_TRUE(!of.octree.level_order && !of.accept_near_hits && of.no_fudge);
}

TEST(AccelSettingsFromSwitches, ThreadsReachTheBuilds) {
    SceneHeader octree;
    octree.sptncde = 1;
    octree.octr = 4;
    EXPECT_EQ(accel_for(octree, {}).build_threads, 0U);
    EXPECT_EQ(accel_for(octree, {"--threads", "3"}).build_threads, 3U);
    EXPECT_EQ(accel_for(octree, {"--threads", "1", "--accel", "bvh"}).build_threads, 1U);
}

}  // namespace
}  // namespace rt
