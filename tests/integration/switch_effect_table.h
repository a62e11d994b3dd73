// Every switch of the manual, and what it must do to a picture (issue: "a switch that is
// ignored, or whose meaning is swapped with another's, fails its row").
//
// A picture row renders a scene with and without the switch and states, region by region, how the
// picture must change: brighter, darker, changed, or the same. The regions are rectangles of
// scenes/gallery.scn (or a variant), chosen where the manual says the switch acts. A row is proven
// twice: its own picture must meet every expectation, and the picture of every other switch on the
// same scene must fail at least one of them, so that no two switches can trade meanings unseen.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "picture_regions.h"

namespace rt::test {

enum class Effect {
    Brighter,        ///< the region's mean rises by at least `amount` levels (1 is 255)
    Darker,          ///< the region's mean falls by at least `amount` levels
    Within,          ///< the mean moves by between `amount` and `high` levels (signed)
    Changes,         ///< a fraction in [amount, high] of its pixels moves by half a level or more
    Touches,         ///< at least a fraction `amount` of its pixels moves at all
    Same,            ///< no pixel moves at all: at most a fraction `amount` is touched
    DisplayRatio,    ///< the 8-bit picture's mean, over the base's, is in [amount, high]
    DisplayChanges,  ///< at least a fraction `amount` of its 8-bit pixels moves by more than 1
};

struct Expect {
    std::string_view region;
    Effect effect = Effect::Changes;
    double amount = 0.0;
    double high = 1.0;  ///< Within, Changes and DisplayRatio
    int channel = -1;   ///< Brighter, Darker, Within: 0 red, 1 green, 2 blue; -1 their mean
};

/// A scene and the switches every picture of it is rendered with.
struct TestScene {
    std::string_view name;
    std::string_view scene;            ///< under scenes/
    std::string_view variant;          ///< "original", or a dialect of scene_variants.h
    std::vector<std::string> context;  ///< given to every picture of it
    std::vector<Region> regions;
};

struct PictureRow {
    std::string_view spelling;          ///< the switch table's row it proves: "-Dr"
    std::vector<std::string> switches;  ///< as typed: {"-Dr"}, {"-Wc", "0.5"}
    std::string_view setup;             ///< the TestScene both pictures are rendered from
    std::vector<Expect> expects;
    std::string_view what;  ///< the manual's words for what must happen
    /// Switches whose pictures may meet these expectations too, and why: -O1 is -Oi taking
    /// every sample.
    std::vector<std::string_view> alike = {};
    /// The base picture's switches (after the context), and its scene when not the row's own.
    std::vector<std::string> base = {};
    std::string_view base_setup = {};
    /// Text that rt must print (debugging switches), or empty.
    std::string_view prints = {};
};

/// A switch that does not draw a different picture, and what shows that it works.
struct OtherSwitch {
    std::string_view spelling;
    std::string_view shown_by;
};

const std::vector<TestScene>& test_scenes();
const std::vector<PictureRow>& picture_rows();
/// Every switch of the table that is not proven by a picture row, with where it is proven.
const std::vector<OtherSwitch>& other_switches();

}  // namespace rt::test
