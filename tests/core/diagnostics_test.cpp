// Diagnostics: warnings and notes are always kept and also go to their sink; parse traces exist
// only while someone listens.
#include "rt/core/diagnostics.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(Diagnostics, KeepsWarningsAndNotesWithOrWithoutASink) {
    Diagnostics d;
    d.warn("w1");
    d.note("n1");
    std::vector<std::string> shown;
    d.set_warning_sink([&](const std::string& m) { shown.push_back("warning " + m); });
    d.set_note_sink([&](const std::string& m) { shown.push_back("note " + m); });
    d.warn("w2");
    d.note("n2");
    EXPECT_EQ(d.warnings(), (std::vector<std::string>{"w1", "w2"}));
    EXPECT_EQ(d.notes(), (std::vector<std::string>{"n1", "n2"}));
    EXPECT_EQ(shown, (std::vector<std::string>{"warning w2", "note n2"}));
}

TEST(Diagnostics, TracesOnlyWhileTracing) {
    Diagnostics d;
    EXPECT_FALSE(d.tracing());
    d.trace("lost");
    std::vector<std::string> traced;
    d.set_trace_sink([&](const std::string& m) { traced.push_back(m); });
    EXPECT_TRUE(d.tracing());
    d.trace("kept");
    EXPECT_EQ(traced, std::vector<std::string>{"kept"});
    EXPECT_TRUE(d.warnings().empty());
    EXPECT_TRUE(d.notes().empty());
}

// A warning that comes once a polygon: a bad model of 100,000 would print 100,000 lines. The first
// ten of each kind are shown, and one line counts the rest.
TEST(Diagnostics, ShowsTheFirstTenOfAKindAndCountsTheRest) {
    Diagnostics d;
    std::vector<std::string> shown;
    d.set_warning_sink([&](const std::string& m) { shown.push_back(m); });
    for (int i = 1; i <= 25; ++i) {
        d.warn_repeated("degenerate polygons in a.obj", "a.obj: polygon " + std::to_string(i));
    }
    d.warn_repeated("degenerate cells in grid", "grid:3: cell 1");
    d.warn("once");
    EXPECT_EQ(shown.size(), 12u);
    EXPECT_EQ(shown[9], "a.obj: polygon 10");
    EXPECT_EQ(shown[10], "grid:3: cell 1");
    d.finish_repeats();
    ASSERT_EQ(shown.size(), 13u);
    EXPECT_EQ(shown.back(),
              "15 more degenerate polygons in a.obj skipped (the first 10 are named above)");
    EXPECT_EQ(d.warnings(), shown);
    // Counting starts again for the next scene.
    d.warn_repeated("degenerate polygons in a.obj", "a.obj: polygon 1");
    d.finish_repeats();
    EXPECT_EQ(shown.back(), "a.obj: polygon 1");
}

TEST(Diagnostics, TenOfAKindNeedNoCount) {
    Diagnostics d;
    for (int i = 0; i < 10; ++i) {
        d.warn_repeated("k", "w");
    }
    d.finish_repeats();
    EXPECT_EQ(d.warnings().size(), 10u);
}

}  // namespace
}  // namespace rt
