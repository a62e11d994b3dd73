// The progress report with a clock the test moves by hand and a string stream for the terminal:
// what it prints and how often, never how long anything takes.
#include "rt/app/progress_report.h"

#include <cstdint>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace rt {
namespace {

constexpr const char* kErase = "\r\033[K";

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

// A report on a string, with a clock at `now` seconds.
struct Fixture {
    std::ostringstream out;
    double now = 100.0;
    ProgressReport report;
    explicit Fixture(ProgressReport::Style style) : report(out, style, [this] { return now; }) {}
};

TEST(ProgressFigures, DurationsAndRatesReadAtAGlance) {
    EXPECT_EQ(format_duration(0.0), "0:00");
    EXPECT_EQ(format_duration(7.4), "0:07");
    EXPECT_EQ(format_duration(754.0), "12:34");
    EXPECT_EQ(format_duration(3723.0), "1:02:03");
    EXPECT_EQ(format_duration(-3.0), "0:00");
    EXPECT_EQ(format_rate(0.0), "0");
    EXPECT_EQ(format_rate(950.2), "950");
    EXPECT_EQ(format_rate(1234.0), "1.23k");
    EXPECT_EQ(format_rate(45600.0), "45.6k");
    EXPECT_EQ(format_rate(456000.0), "456k");
    EXPECT_EQ(format_rate(9999.0), "10.0k");
    EXPECT_EQ(format_rate(1234567.0), "1.23M");
}

TEST(ProgressFigures, TimeLeftScalesTheTimeSpentByTheRowsToDo) {
    ProgressFigures f{0, 400, 0, 3.0};
    EXPECT_FALSE(f.seconds_left().has_value());  // nothing to go by yet
    EXPECT_EQ(f.samples_per_second(), 0.0);
    f = {100, 400, 20000, 10.0};
    ASSERT_TRUE(f.seconds_left().has_value());
    EXPECT_DOUBLE_EQ(*f.seconds_left(), 30.0);
    EXPECT_DOUBLE_EQ(f.samples_per_second(), 2000.0);
    EXPECT_DOUBLE_EQ(f.fraction(), 0.25);
    f = {400, 400, 80000, 40.0};
    EXPECT_DOUBLE_EQ(*f.seconds_left(), 0.0);
}

TEST(ProgressFigures, BarAndLineText) {
    const ProgressFigures f{123, 400, 547200, 12.0};
    EXPECT_EQ(progress_bar_text(f),
              "[######..............] 123/400 lines  45.6k samples/s  0:12 elapsed  0:27 left");
    EXPECT_EQ(progress_line_text(f),
              "123 of 400 lines (30 %), 45.6k samples/s, 0:12 elapsed, 0:27 left");
    EXPECT_EQ(progress_bar_text({5, 400, 0, 0.0}),
              "[....................]   5/400 lines  0 samples/s  0:00 elapsed  0:00 left");
    EXPECT_EQ(progress_line_text({0, 400, 0, 0.0}),
              "0 of 400 lines (0 %), 0 samples/s, 0:00 elapsed, ?:?? left");
    EXPECT_EQ(progress_bar_text({400, 400, 1000, 2.0}).substr(0, 22), "[####################]");
}

TEST(ProgressReport, ABarIsRedrawnInPlaceAtMostTenTimesASecond) {
    Fixture t(ProgressReport::Style::Bar);
    t.report.update(0, 400, 0);
    EXPECT_EQ(t.out.str(), std::string(kErase) + "rt: " + progress_bar_text({0, 400, 0, 0.0}));
    // 400 rows, one every 10 ms: four seconds.
    for (int row = 1; row <= 400; ++row) {
        t.now += 0.01;
        t.report.update(row, 400, static_cast<std::uint64_t>(row) * 512);
    }
    const std::string text = t.out.str();
    const std::size_t draws = count(text, kErase);
    EXPECT_LE(draws, 4 / ProgressReport::kBarInterval + 2);
    EXPECT_GE(draws, 2 / ProgressReport::kBarInterval);
    EXPECT_EQ(count(text, "\n"), 1U);  // only the last state ends its line
    const std::string last = text.substr(text.rfind(kErase));
    EXPECT_EQ(last,
              std::string(kErase) + "rt: " + progress_bar_text({400, 400, 204800, 4.0}) + "\n");
}

TEST(ProgressReport, MessagesGoAboveTheBarNotIntoIt) {
    Fixture t(ProgressReport::Style::Bar);
    t.report.update(0, 10, 0);
    t.now += 1.0;
    t.report.update(1, 10, 100);
    t.out.str("");
    t.now += 1.0;
    t.report.print_line("rt: warning: something");
    // The bar is erased, the message printed on its own line, and the bar drawn again below.
    EXPECT_EQ(t.out.str(), std::string(kErase) + "rt: warning: something\n" + kErase +
                               "rt: " + progress_bar_text({1, 10, 100, 2.0}));
    // A flood of messages does not redraw the bar for each one.
    t.out.str("");
    for (int i = 0; i < 100; ++i) {
        t.now += 0.001;
        t.report.print_line("line 1 column " + std::to_string(i));
    }
    EXPECT_EQ(count(t.out.str(), "\n"), 100U);
    EXPECT_LE(count(t.out.str(), "rt: ["), 1U);
}

TEST(ProgressReport, ABarLeftOnScreenEndsItsLineWhenTheReportGoes) {
    std::ostringstream out;
    {
        ProgressReport report(out, ProgressReport::Style::Bar, [] { return 0.0; });
        report.update(0, 10, 0);
    }
    EXPECT_EQ(out.str().back(), '\n');
    EXPECT_EQ(count(out.str(), "\n"), 1U);
}

TEST(ProgressReport, ElsewhereAPlainLineEveryFiveSeconds) {
    Fixture t(ProgressReport::Style::Lines);
    t.report.update(0, 12, 0);
    for (int row = 1; row <= 12; ++row) {
        t.now += 1.0;
        t.report.update(row, 12, static_cast<std::uint64_t>(row) * 100);
    }
    EXPECT_EQ(t.out.str(),
              "rt: 5 of 12 lines (41 %), 100 samples/s, 0:05 elapsed, 0:07 left\n"
              "rt: 10 of 12 lines (83 %), 100 samples/s, 0:10 elapsed, 0:02 left\n"
              "rt: 12 of 12 lines (100 %), 100 samples/s, 0:12 elapsed, 0:00 left\n");
    t.report.print_line("rt: a note");
    EXPECT_EQ(t.out.str().substr(t.out.str().size() - 11), "rt: a note\n");
}

TEST(ProgressReport, AShortRenderElsewherePrintsNothing) {
    Fixture t(ProgressReport::Style::Lines);
    t.report.update(0, 100, 0);
    for (int row = 1; row <= 100; ++row) {
        t.now += 0.04;
        t.report.update(row, 100, 10);
    }
    EXPECT_EQ(t.out.str(), "");
}

}  // namespace
}  // namespace rt
