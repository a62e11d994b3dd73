// The switch-effect table (switch_effect_table.h) run against the rt program: each row's own
// picture meets its expectations, no other switch's picture does, and every switch of rt's table
// has a row or a stated proof elsewhere.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "rt/app/switch_table.h"
#include "rt/image/png_format.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include "picture_regions.h"
#include "scene_variants.h"
#include "support/temp_dir.h"
#include "switch_effect_table.h"

namespace rt::test {

std::ostream& operator<<(std::ostream& out, const PictureRow& row) {
    return out << fmt::format("{} ({})", fmt::join(row.switches, " "), row.setup);
}

namespace {

namespace fs = std::filesystem;

const TestScene& scene_named(std::string_view name) {
    for (const TestScene& s : test_scenes()) {
        if (s.name == name) {
            return s;
        }
    }
    throw std::out_of_range("no test scene " + std::string(name));
}

const Region& region_named(const TestScene& scene, std::string_view name) {
    for (const Region& r : scene.regions) {
        if (r.name == name) {
            return r;
        }
    }
    throw std::out_of_range("no region " + std::string(name) + " in " + std::string(scene.name));
}

// Renders test scenes with extra switches; each picture is drawn once per test program run.
class Renderer {
public:
    const Picture* picture(const TestScene& scene, const std::vector<std::string>& extra) {
        std::vector<std::string> switches = scene.context;
        switches.insert(switches.end(), extra.begin(), extra.end());
        const std::string key =
            fmt::format("{}/{} {}", scene.variant, scene.scene, fmt::join(switches, " "));
        auto found = pictures_.find(key);
        if (found == pictures_.end()) {
            std::string error;
            std::optional<Picture> made =
                render_picture(scene_path(scene), switches, folder_.path(), error);
            found = pictures_.emplace(key, std::move(made)).first;
            errors_[key] = error;
        }
        last_error_ = errors_[key];
        return found->second ? &*found->second : nullptr;
    }
    const std::string& last_error() const { return last_error_; }

private:
    fs::path scene_path(const TestScene& scene) {
        if (scene.variant == "original") {
            return source_dir() / "scenes" / std::string(scene.scene);
        }
        const std::string variant(scene.variant);
        if (!variants_.contains(variant)) {
            variants_[variant] = write_gallery_variant(variant, folder_.path() / variant);
        }
        return variants_[variant];
    }

    TempDir folder_;
    std::map<std::string, fs::path> variants_;
    std::map<std::string, std::optional<Picture>> pictures_;
    std::map<std::string, std::string> errors_;
    std::string last_error_;
};

Renderer& renderer() {
    static Renderer shared;
    return shared;
}

const Picture* base_picture(const PictureRow& row) {
    const TestScene& scene = scene_named(row.base_setup.empty() ? row.setup : row.base_setup);
    return renderer().picture(scene, row.base);
}

// "" when the expectation holds, else what was found instead.
std::string check(const Expect& e, const RegionChange& c) {
    const double moved = e.channel < 0 ? c.mean() : c.mean_difference[e.channel];
    const std::string channel = e.channel < 0 ? "" : fmt::format(" (channel {})", e.channel);
    const auto found = [&](const std::string& what) {
        return fmt::format("{}{}: {}", e.region, channel, what);
    };
    switch (e.effect) {
        case Effect::Brighter:
            return moved >= e.amount
                       ? ""
                       : found(fmt::format("brighter by {:.2f} levels, not {}", moved, e.amount));
        case Effect::Darker:
            return -moved >= e.amount
                       ? ""
                       : found(fmt::format("darker by {:.2f} levels, not {}", -moved, e.amount));
        case Effect::Within:
            return moved >= e.amount && moved <= e.high
                       ? ""
                       : found(fmt::format("moved {:+.2f} levels, not in [{}, {}]", moved, e.amount,
                                           e.high));
        case Effect::Changes:
            return c.changed_fraction >= e.amount && c.changed_fraction <= e.high
                       ? ""
                       : found(fmt::format("{:.3f} of the pixels changed, not in [{}, {}]",
                                           c.changed_fraction, e.amount, e.high));
        case Effect::Touches:
            return c.touched_fraction >= e.amount
                       ? ""
                       : found(fmt::format("{:.3f} of the pixels moved, not {}", c.touched_fraction,
                                           e.amount));
        case Effect::Same:
            return c.touched_fraction <= e.amount
                       ? ""
                       : found(fmt::format("{:.3f} of the pixels moved, at most {}",
                                           c.touched_fraction, e.amount));
        case Effect::DisplayRatio:
            return c.display_ratio >= e.amount && c.display_ratio <= e.high
                       ? ""
                       : found(fmt::format("displayed {:.3f} times as bright, not in [{}, {}]",
                                           c.display_ratio, e.amount, e.high));
        case Effect::DisplayChanges:
            return c.display_changed >= e.amount
                       ? ""
                       : found(fmt::format("{:.3f} of the displayed pixels changed, not {}",
                                           c.display_changed, e.amount));
    }
    return "?";
}

// Every expectation of the row that `picture` fails, measured against the row's base.
std::vector<std::string> failures(const PictureRow& row, const Picture& base,
                                  const Picture& picture) {
    const TestScene& scene = scene_named(row.setup);
    std::vector<std::string> failed;
    for (const Expect& e : row.expects) {
        std::string f = check(e, measure_change(base, picture, region_named(scene, e.region)));
        if (!f.empty()) {
            failed.push_back(std::move(f));
        }
    }
    return failed;
}

// --- each row's own picture -------------------------------------------------------------------

class SwitchEffect : public ::testing::TestWithParam<PictureRow> {};

TEST_P(SwitchEffect, ChangesThePictureWhereTheManualSays) {
    const PictureRow& row = GetParam();
    ASSERT_FALSE(row.expects.empty()) << "a row must expect something";
    const Picture* base = base_picture(row);
    ASSERT_NE(base, nullptr) << renderer().last_error();
    const Picture* picture = renderer().picture(scene_named(row.setup), row.switches);
    ASSERT_NE(picture, nullptr) << renderer().last_error();
    for (const std::string& f : failures(row, *base, *picture)) {
        ADD_FAILURE() << row.what << "\n  " << f;
    }
    EXPECT_NE(picture->output.find(row.prints), std::string::npos)
        << row.what << "\n  rt did not print '" << row.prints << "'";
}

std::string row_name(const ::testing::TestParamInfo<PictureRow>& info) {
    std::string name = fmt::format("{}_{}", info.param.setup, fmt::join(info.param.switches, ""));
    for (char& c : name) {
        if (std::isalnum(static_cast<unsigned char>(c)) == 0) {
            c = '_';
        }
    }
    return name + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(Table, SwitchEffect, ::testing::ValuesIn(picture_rows()), row_name);

// --- no other switch's picture passes a row ---------------------------------------------------

// The switches that make a row's effect: its switches less those of its base.
std::vector<std::string> effect_switches(const PictureRow& row) {
    std::vector<std::string> effect;
    for (const std::string& s : row.switches) {
        if (std::find(row.base.begin(), row.base.end(), s) == row.base.end()) {
            effect.push_back(s);
        }
    }
    return effect;
}

bool expects_only_sameness(const PictureRow& row) {
    return std::all_of(row.expects.begin(), row.expects.end(),
                       [](const Expect& e) { return e.effect == Effect::Same; });
}

// The scenes whose rows are compared with every other switch: those whose rows differ from
// their base by switches alone (not by another scene file).
std::vector<std::string> cross_checked_scenes() {
    std::vector<std::string> names;
    for (const PictureRow& row : picture_rows()) {
        if (row.base_setup.empty() && !expects_only_sameness(row) &&
            std::find(names.begin(), names.end(), row.setup) == names.end()) {
            names.emplace_back(row.setup);
        }
    }
    return names;
}

class NoOtherSwitch : public ::testing::TestWithParam<std::string> {};

// If a row's switch did what another switch does, its picture would be that other switch's
// picture; so no other switch's picture may meet the row's expectations. (Switches that must
// leave the picture alone are left out: a row whose switch did nothing fails by itself.)
TEST_P(NoOtherSwitch, MeetsARowsExpectations) {
    int compared = 0;
    for (const PictureRow& row : picture_rows()) {
        if (row.setup != GetParam() || !row.base_setup.empty() || expects_only_sameness(row)) {
            continue;
        }
        const Picture* base = base_picture(row);
        ASSERT_NE(base, nullptr) << renderer().last_error();
        for (const PictureRow& other : picture_rows()) {
            const std::vector<std::string> effect = effect_switches(other);
            if (other.spelling == row.spelling || effect.empty() || expects_only_sameness(other) ||
                std::find(row.alike.begin(), row.alike.end(), other.spelling) != row.alike.end()) {
                continue;
            }
            std::vector<std::string> switches = row.base;
            switches.insert(switches.end(), effect.begin(), effect.end());
            const Picture* picture = renderer().picture(scene_named(row.setup), switches);
            if (picture == nullptr) {
                continue;  // rt refuses the combination (another dialect, an exclusive group)
            }
            ++compared;
            EXPECT_FALSE(failures(row, *base, *picture).empty())
                << "the picture of " << fmt::format("{}", fmt::join(switches, " "))
                << " meets every expectation of the row " << row;
        }
    }
    EXPECT_GT(compared, 10);
}

std::string scene_name(const ::testing::TestParamInfo<std::string>& scene) {
    std::string name = scene.param;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

INSTANTIATE_TEST_SUITE_P(Table, NoOtherSwitch, ::testing::ValuesIn(cross_checked_scenes()),
                         scene_name);

// --- every switch has its row ----------------------------------------------------------------

bool listed(std::string_view spelling) {
    const auto& rows = picture_rows();
    const auto& others = other_switches();
    return std::any_of(rows.begin(), rows.end(),
                       [&](const PictureRow& r) { return r.spelling == spelling; }) ||
           std::any_of(others.begin(), others.end(),
                       [&](const OtherSwitch& o) { return o.spelling == spelling; });
}

TEST(SwitchEffectTable, ListsEverySwitchOfRt) {
    std::set<std::string_view> spellings;
    for (const SwitchSpec& spec : switch_table()) {
        spellings.insert(spec.spelling);
        if (spec.status == Status::NotYet) {
            continue;  // refused: see RefusesTheSwitchesNotDoneYet
        }
        EXPECT_TRUE(listed(spec.spelling)) << spec.spelling << " has no row";
    }
    for (const PictureRow& row : picture_rows()) {
        EXPECT_TRUE(spellings.contains(row.spelling)) << "no switch " << row.spelling;
    }
    for (const OtherSwitch& other : other_switches()) {
        EXPECT_TRUE(spellings.contains(other.spelling)) << "no switch " << other.spelling;
    }
}

TEST(SwitchEffectTable, RefusesTheSwitchesNotDoneYet) {
    for (const SwitchSpec& spec : switch_table()) {
        if (spec.status != Status::NotYet) {
            continue;
        }
        EXPECT_EQ(renderer().picture(scene_named("gallery"), {std::string(spec.spelling)}), nullptr)
            << spec.spelling;
        EXPECT_NE(renderer().last_error().find("not implemented yet"), std::string::npos)
            << spec.spelling << ": " << renderer().last_error();
    }
}

// -L60 "draws only from line 60 up": rows 0 to 60 of the picture, as they were.
TEST(SwitchEffectTable, LDrawsOnlyFromThatLineUp) {
    const Picture* whole = renderer().picture(scene_named("gallery"), {});
    ASSERT_NE(whole, nullptr) << renderer().last_error();
    const Picture* cut = renderer().picture(scene_named("gallery"), {"-L60"});
    ASSERT_NE(cut, nullptr) << renderer().last_error();
    ASSERT_EQ(cut->width, whole->width);
    ASSERT_EQ(cut->height, 61);
    EXPECT_TRUE(std::equal(cut->levels.begin(), cut->levels.end(), whole->levels.begin()));
}

// --- tuning aid: RT_SWITCH_EFFECT_DUMP=folder draws every row's difference --------------------

Image8 difference(const Picture& base, const Picture& picture) {
    Image8 image{base.width, base.height, {}};
    image.rgb.reserve(base.levels.size() * 3);
    for (std::size_t k = 0; k < base.levels.size(); ++k) {
        for (int c = 0; c < 3; ++c) {
            const double d = picture.levels[k][c] - base.levels[k][c];
            image.rgb.push_back(static_cast<std::uint8_t>(std::clamp(128.0 + 8.0 * d, 0.0, 255.0)));
        }
    }
    return image;
}

TEST(SwitchEffectDump, WritesDifferencePictures) {
    // Read before any thread starts: this test runs alone, by hand.
    const char* folder = std::getenv("RT_SWITCH_EFFECT_DUMP");  // NOLINT(concurrency-mt-unsafe)
    if (folder == nullptr) {
        GTEST_SKIP() << "set RT_SWITCH_EFFECT_DUMP=folder to draw every row's difference";
    }
    for (const PictureRow& row : picture_rows()) {
        const Picture* base = base_picture(row);
        const Picture* p = renderer().picture(scene_named(row.setup), row.switches);
        const std::string name = fmt::format("{}{}", row.setup, fmt::join(row.switches, ""));
        if (base == nullptr || p == nullptr) {
            std::cout << name << ": " << renderer().last_error();
            continue;
        }
        write_png(difference(*base, *p), fs::path(folder) / (name + ".png"));
        std::cout << name << "\n";
        for (const Region& r : scene_named(row.setup).regions) {
            if (r.bottom >= p->height || r.bottom >= base->height) {
                continue;  // a picture cut by -L has fewer rows than the region needs
            }
            const RegionChange c = measure_change(*base, *p, r);
            std::cout << fmt::format(
                "  {:<13} {:+7.2f} ({:+7.2f} {:+7.2f} {:+7.2f}) changed {:.2f} touched {:.2f} "
                "display x{:.3f} changed {:.2f}\n",
                r.name, c.mean(), c.mean_difference.r, c.mean_difference.g, c.mean_difference.b,
                c.changed_fraction, c.touched_fraction, c.display_ratio, c.display_changed);
        }
    }
}

}  // namespace
}  // namespace rt::test
