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

}  // namespace
}  // namespace rt
