// The switch table's own promises: every Appendix switch is a row, spellings never collide, and
// each row's example parses to that row and sets what the row says.
#include "rt/app/switch_table.h"

#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "rt/app/switch_parser.h"
#include "rt/core/error.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

std::vector<std::string> words(std::string_view text) {
    std::istringstream in{std::string(text)};
    std::vector<std::string> result;
    for (std::string word; in >> word;) {
        result.push_back(word);
    }
    return result;
}

// The example after a scene (but --model takes the scene's place).
Options parse_example(const SwitchSpec& spec) {
    std::vector<std::string> args;
    if (spec.spelling != "--model") {
        args.emplace_back("twocubes");
    }
    for (std::string& word : words(spec.example)) {
        args.push_back(std::move(word));
    }
    return parse_command_line(args);
}

TEST(SwitchTable, HasEverySwitchOfTheAppendixAndTheLongOptions) {
    const std::vector<std::string_view> expected = {
        "-n",          "-w",          "-m",        "-tv",      "-c",      "-od",       "-oo",
        "-ol",         "-on",         "-of",       "-op",      "-ss",     "-p",        "-r",
        "-Sp",         "-Sg",         "-Stg",      "-Stb",     "-R",      "-Wr",       "-Wc",
        "-Wt",         "-A",          "-T",        "-Co",      "-Ci",     "-Cf",       "-Dx",
        "-De",         "-Dd",         "-Dt",       "-Da",      "-Dl",     "-Ds",       "-Dr",
        "-Df",         "-Dp",         "-Db",       "-Po",      "-Pt",     "-Ot",       "-Oi",
        "-Of",         "-O1",         "-K",        "-I",       "-L",      "-E",        "-F",
        "-Xp",         "-Xr",         "-M",        "-V",       "-dc",     "-ds",       "-dsp",
        "-dso",        "-dl",         "-doo",      "-doi",     "-dof",    "-df",       "-dd",
        "-dx",         "-de",         "--output",  "--resume", "--model", "--help",    "--version",
        "--seed",      "--cutoff",    "--threads", "--tile",   "--accel", "--zbuffer", "--quiet",
        "--no-window", "--max-memory"};
    std::vector<std::string_view> actual;
    for (const SwitchSpec& spec : switch_table()) {
        actual.push_back(spec.spelling);
    }
    EXPECT_EQ(actual, expected);
}

TEST(SwitchTable, SpellingsAndAliasesAreUnique) {
    std::set<std::string_view> seen;
    for (const SwitchSpec& spec : switch_table()) {
        EXPECT_TRUE(seen.insert(spec.spelling).second) << spec.spelling;
        if (!spec.alias.empty()) {
            EXPECT_TRUE(seen.insert(spec.alias).second) << spec.alias;
        }
    }
}

TEST(SwitchTable, EveryRowHasHelpSectionAndExample) {
    for (const SwitchSpec& spec : switch_table()) {
        EXPECT_FALSE(spec.summary.empty()) << spec.spelling;
        EXPECT_FALSE(spec.section.empty()) << spec.spelling;
        EXPECT_TRUE(spec.example.starts_with(spec.spelling)) << spec.spelling;
        EXPECT_NE(spec.apply, nullptr) << spec.spelling;
        EXPECT_EQ(spec.status == Status::NotYet, !spec.feature.empty()) << spec.spelling;
        EXPECT_EQ(spec.first.name.empty(), spec.form == ArgForm::None) << spec.spelling;
    }
}

// Where one spelling begins another (-ds, -dsp), the longest match must still pick each row.
TEST(SwitchTable, EachExampleMatchesItsOwnRow) {
    int prefix_pairs = 0;
    for (const SwitchSpec& spec : switch_table()) {
        EXPECT_EQ(match_switch(words(spec.example).front()), &spec) << spec.example;
        for (const SwitchSpec& other : switch_table()) {
            if (&other != &spec && other.spelling.starts_with(spec.spelling)) {
                ++prefix_pairs;
                EXPECT_EQ(match_switch(other.spelling), &other) << other.spelling;
            }
        }
    }
    EXPECT_GE(prefix_pairs, 2);  // -ds before -dsp and -dso
}

TEST(SwitchTable, NotYetRowsAreRefusedByName) {
    for (const SwitchSpec& spec : switch_table()) {
        if (spec.status == Status::Implemented) {
            EXPECT_NO_THROW(parse_example(spec)) << spec.example;
            continue;
        }
        try {
            parse_example(spec);
            ADD_FAILURE() << spec.example << " was accepted";
        } catch (const NotImplementedError& e) {
            EXPECT_EQ(std::string(e.what()), std::string(spec.spelling) + ": " +
                                                 std::string(spec.feature) +
                                                 " is not implemented yet");
        }
    }
}

TEST(SwitchTable, StatusesOfThisRelease) {
    const std::set<std::string_view> implemented = {
        "-n",   "-m",   "-c",  "-A",   "-Da", "-Dl",  "-Ds", "-Dr", "-Dt",  "-Db", "-T",
        "-Dd",  "-Dx",  "-Df", "-Dp",  "-Of", "-R",   "-M",  "-Po", "-Pt",  "-Sp", "-L",
        "-dc",  "-df",  "-I",  "-Xp",  "-Xr", "-dx",  "-F",  "-Oi", "-O1",  "-Sg", "-Stg",
        "-Stb", "-Co",  "-Ci", "-Cf",  "-Wr", "-Wc",  "-Wt", "-K",  "-p",   "-r",  "-E",
        "-Ot",  "-De",  "-de", "-tv",  "-od", "-ol",  "-on", "-of", "-op",  "-ss", "-ds",
        "-dsp", "-dso", "-dl", "-doo", "-dd", "-dof", "-w",  "-oo", "-doi", "-V"};
    for (const SwitchSpec& spec : switch_table()) {
        const std::set<std::string_view> long_not_yet = {};
        const bool expected = (spec.is_long_option() && !long_not_yet.contains(spec.spelling)) ||
                              implemented.contains(spec.spelling);
        EXPECT_EQ(spec.status == Status::Implemented, expected) << spec.spelling;
    }
}

using Check = std::function<bool(const Options&)>;

// What each row sets. Implemented rows are checked through the parser with their example;
// NotYet rows (which the parser refuses) by calling apply with the example's argument.
struct Expectation {
    SwitchArgument argument;
    Check holds;
};

SwitchArgument number(double value) {
    SwitchArgument argument;
    argument.first = value;
    return argument;
}

SwitchArgument pair(double first, double second) {
    SwitchArgument argument = number(first);
    argument.second = second;
    return argument;
}

SwitchArgument whole(std::int64_t value) {
    SwitchArgument argument;
    argument.integer = value;
    return argument;
}

std::map<std::string_view, Expectation> expectations() {
    auto flag = [](bool Options::*field) {
        return Expectation{{}, [field](const Options& o) { return o.*field; }};
    };
    auto shading_flag = [](bool ShadingSettings::*field, bool value) {
        return Expectation{{},
                           [field, value](const Options& o) { return o.shading.*field == value; }};
    };
    auto tint = [](HighlightTint wanted) {
        return Expectation{
            {}, [wanted](const Options& o) { return o.shading.specular.tint == wanted; }};
    };
    std::map<std::string_view, Expectation> e = {
        {"-n", flag(&Options::no_gro)},
        {"-w", flag(&Options::wireframe_only)},
        {"-m", {{}, [](const Options& o) { return o.display.multiplier == 2.0; }}},
        {"-tv",
         {whole(8), [](const Options& o) { return o.accel.method.terminate_after_voxels == 8; }}},
        {"-c", {{}, [](const Options& o) { return !o.display.clip; }}},
        {"-od", {whole(5), [](const Options& o) { return o.accel.method.octree.depth == 5; }}},
        {"-oo", flag(&Options::draw_octree)},
        {"-ol",
         {whole(16), [](const Options& o) { return o.accel.method.octree.octlist_power == 16; }}},
        {"-on", {{}, [](const Options& o) { return o.accel.method.accept_near_hits; }}},
        {"-of", {{}, [](const Options& o) { return o.accel.method.no_fudge; }}},
        {"-op", {{}, [](const Options& o) { return o.accel.method.octree.level_order; }}},
        {"-ss",
         {whole(10), [](const Options& o) { return o.accel.method.octree.seed_size_power == 10; }}},
        {"-p", flag(&Options::profile)},
        {"-r", flag(&Options::random_rays)},
        {"-Sp",
         {{},
          [](const Options& o) {  // the default, so also look for the switch itself
              return o.shading.specular.law() == SpecularLaw::Phong && o.given_switches.size() == 1;
          }}},
        {"-Sg",
         {{},
          [](const Options& o) {
              return o.shading.specular.law() == SpecularLaw::PhongGeometric;
          }}},
        {"-Stg",
         {number(1.0),
          [](const Options& o) {
              return o.shading.specular.law() == SpecularLaw::TorranceSparrowGaussian &&
                     o.shading.specular.slope_m() == 1.0;
          }}},
        {"-Stb",
         {number(1.0),
          [](const Options& o) {
              return o.shading.specular.law() == SpecularLaw::TorranceSparrowBeckmann &&
                     o.shading.specular.slope_m() == 1.0;
          }}},
        {"-R", {{}, [](const Options& o) { return o.dialect.rgb_refraction; }}},
        {"-Wr", {{}, [](const Options& o) { return o.shading.warn.mode == WarnMode::Rogers; }}},
        {"-Wc",
         {number(0.7),
          [](const Options& o) {
              return o.shading.warn.mode == WarnMode::Conical && o.shading.warn.cone_angle == 0.7;
          }}},
        {"-Wt",
         {number(1.0),
          [](const Options& o) {
              return o.shading.warn.mode == WarnMode::Thibadeau &&
                     o.shading.warn.displacement == 1.0;
          }}},
        {"-A",
         {{},
          [](const Options& o) {
              return o.shading.attenuation_distance == 40.0 &&
                     o.shading.attenuation_constant == 1.0;
          }}},
        {"-T", shading_flag(&ShadingSettings::far_side_feelers, true)},
        {"-Co", tint(HighlightTint::ObjectColor)},
        {"-Ci",
         {{},
          [](const Options& o) {  // the default, so also look for the switch itself
              return o.shading.specular.tint == HighlightTint::LightColor &&
                     o.given_switches.size() == 1;
          }}},
        {"-Cf", tint(HighlightTint::Fresnel)},
        {"-Dx", {{}, [](const Options& o) { return !o.shading.sampling.adaptive; }}},
        {"-De", {{}, [](const Options& o) { return !o.accel.exit_culling; }}},
        {"-Dd", {{}, [](const Options& o) { return !o.shading.sampling.distribute; }}},
        {"-Dt", shading_flag(&ShadingSettings::feelers_stop_at_transparent, true)},
        {"-Da", shading_flag(&ShadingSettings::attenuate_rays, false)},
        {"-Dl", shading_flag(&ShadingSettings::attenuate_feelers, false)},
        {"-Ds", shading_flag(&ShadingSettings::shadow_feelers, false)},
        {"-Dr", shading_flag(&ShadingSettings::reflection, false)},
        {"-Df",
         {{},
          [](const Options& o) {
              return o.dialect.attributes_inline && !o.dialect.no_power_fields;
          }}},
        {"-Dp",
         {{},
          [](const Options& o) {
              return o.dialect.no_power_fields && !o.dialect.attributes_inline;
          }}},
        {"-Db", shading_flag(&ShadingSettings::both_sides_emit, false)},
        {"-Po",
         {{},
          [](const Options& o) {
              return o.shading.smooth_shaded_opaque && o.dialect.smooth_shade_field;
          }}},
        {"-Pt",
         {{},
          [](const Options& o) {
              return !o.shading.smooth_shaded_opaque && o.dialect.smooth_shade_field;
          }}},
        {"-Ot", shading_flag(&ShadingSettings::correct_smoothing, false)},
        {"-Oi", {{}, [](const Options& o) { return o.early == EarlyVersion::OldIllumination; }}},
        {"-Of",
         {{},
          [](const Options& o) {
              return o.dialect.attributes_inline && o.dialect.no_power_fields;
          }}},
        {"-O1", {{}, [](const Options& o) { return o.early == EarlyVersion::OldVersion; }}},
        {"-K", flag(&Options::scale_weights)},
        {"-I", {{}, [](const Options& o) { return o.shading.sampling.illuminate_distributed; }}},
        {"-L", {{}, [](const Options& o) { return o.start_line == 250; }}},
        {"-E", {number(1.5), [](const Options& o) { return o.crease_angle == 1.5; }}},
        {"-F",
         {pair(0.3, 2.0),
          [](const Options& o) {
              return o.shading.fuzzy.angle == 0.3 && o.shading.fuzzy.count == 2;
          }}},
        {"-Xp",
         {pair(0.1, 0.05),
          [](const Options& o) {
              const ChiSquareStop& stop = o.shading.sampling.pixel_stop;
              return stop.probability == 0.1 && stop.variance == 0.05;
          }}},
        {"-Xr",
         {pair(0.1, 0.05),
          [](const Options& o) {
              const ChiSquareStop& stop = o.shading.sampling.ray_stop;
              return stop.probability == 0.1 && stop.variance == 0.05;
          }}},
        {"-M", {{}, [](const Options& o) { return o.dialect.marks; }}},
        {"-V", {{}, [](const Options& o) { return o.dialect.textures; }}},
        {"-dc", flag(&Options::print_columns)},
        {"-ds", {{}, [](const Options& o) { return o.accel.strike_check; }}},
        {"-dsp", {{}, [](const Options& o) { return o.accel.strike_print; }}},
        {"-dso", {{}, [](const Options& o) { return o.accel.strike_voxels; }}},
        {"-dl", {{}, [](const Options& o) { return o.accel.log_intersections; }}},
        {"-doo",
         {{},
          [](const Options& o) {
              return o.accel.octree_listing == std::filesystem::path("octree.lst");
          }}},
        {"-doi", flag(&Options::debug_octree_interactive)},
        {"-dof", {{}, [](const Options& o) { return o.accel.trace_fill; }}},
        {"-df", flag(&Options::trace_parsing)},
        {"-dd", flag(&Options::debug_color)},
        {"-dx", flag(&Options::debug_chi_square)},
        {"-de", {{}, [](const Options& o) { return o.accel.check_exit_culling; }}},
        {"--output",
         {{},
          [](const Options& o) { return o.outputs == std::vector<std::string>{"twocubes.png"}; }}},
        {"--model", {{}, [](const Options& o) { return o.model == "scenes/models/bunny.ply"; }}},
        {"--resume", {{}, [](const Options& o) { return o.resume == "twocubes.gro"; }}},
        {"--seed", {{}, [](const Options& o) { return o.shading.sampling.seed == 7; }}},
        {"--cutoff", {{}, [](const Options& o) { return o.shading.weight_cutoff == 0.01; }}},
        {"--threads", {{}, [](const Options& o) { return o.threads == 2; }}},
        {"--tile",
         {{},
          [](const Options& o) {
              return o.tile == PicturePart{2, 3};
          }}},
        {"--accel", {{}, [](const Options& o) { return o.accel.method.kind == AccelKind::Bvh; }}},
        {"--zbuffer", {{}, [](const Options& o) { return o.accel.zbuffer_first_hits; }}},
        {"--quiet", flag(&Options::quiet)},
        {"--no-window", flag(&Options::no_window)},
        {"--max-memory",
         {{}, [](const Options& o) { return o.max_memory_gib == std::optional<double>(2.0); }}},
        {"--help", flag(&Options::show_help)},
        {"--version", flag(&Options::show_version)},
    };
    return e;
}

TEST(SwitchTable, EachRowSetsItsField) {
    const auto all = expectations();
    for (const SwitchSpec& spec : switch_table()) {
        const auto found = all.find(spec.spelling);
        ASSERT_NE(found, all.end()) << "no expectation for " << spec.spelling;
        const Expectation& expectation = found->second;
        EXPECT_FALSE(expectation.holds(Options{})) << spec.spelling << " holds by default";
        if (spec.status == Status::Implemented) {
            EXPECT_TRUE(expectation.holds(parse_example(spec))) << spec.example;
        } else {
            Options options;
            spec.apply(options, expectation.argument);
            EXPECT_TRUE(expectation.holds(options)) << spec.spelling;
        }
    }
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

// The library names its settings; the program says which switch sets each.
TEST(SwitchTable, NamesTheSwitchesOfASettingError) {
    EXPECT_EQ(name_the_switches("raise the octree node limit, now 2^3, or lower the octree depth"),
              "raise the octree node limit (-ol), now 2^3, or lower the octree depth (-od)");
    EXPECT_EQ(name_the_switches("the microfacet slope m of Torrance-Sparrow must be positive"),
              "the microfacet slope m (-Stg or -Stb) of Torrance-Sparrow must be positive");
    EXPECT_EQ(name_the_switches("use fewer SEADS voxels a side"),
              "use fewer SEADS voxels a side (the scene header's third number, or --accel "
              "seads)");
    EXPECT_EQ(name_the_switches("the start line 19 is above the window's top row 20"),
              "the start line (-L) 19 is above the window's top row 20");
    EXPECT_EQ(name_the_switches("nothing to name"), "nothing to name");
}

}  // namespace
}  // namespace rt
