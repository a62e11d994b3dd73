// Bare `rt`, `rt --help` and --version, all rendered from the switch table.
#include <sstream>
#include <string>

#include "rt/app/help.h"
#include "rt/app/switch_table.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

bool has_line_with(const std::string& text, const std::string& a, const std::string& b) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.find(a) != std::string::npos && line.find(b) != std::string::npos) {
            return true;
        }
    }
    return false;
}

TEST(SwitchHelp, UsageListsEverySwitchOnALineOfItsOwn) {
    const std::string usage = usage_text();
    EXPECT_NE(usage.find("rt SCENE [switches]"), std::string::npos);
    EXPECT_NE(usage.find("--help"), std::string::npos);
    for (const SwitchSpec& spec : switch_table()) {
        if (!spec.is_long_option()) {
            EXPECT_TRUE(has_line_with(usage, "  " + std::string(spec.example) + " ",
                                      std::string(spec.summary)))
                << spec.spelling;
        }
    }
    EXPECT_TRUE(has_line_with(usage, "-w", "  Wireframe only"));
    EXPECT_TRUE(has_line_with(usage, "-Dd", "  disable Distributing"));
}

// The line of a switch's summary in --help: beside its synopsis, or below it when that is long.
std::string summary_line(const std::string& help, const SwitchSpec& spec) {
    for (const char* after : {" ", "\n"}) {
        const std::size_t at = help.find("\n  " + synopsis(spec) + after);
        if (at == std::string::npos) {
            continue;
        }
        std::istringstream in(help.substr(at + 1));
        std::string line;
        std::getline(in, line);
        if (line.find(spec.summary) == std::string::npos) {
            std::getline(in, line);
        }
        return line;
    }
    return "";
}

TEST(SwitchHelp, HelpGivesEverySwitchUnderItsTopic) {
    const std::string help = help_text();
    for (const SwitchSpec& spec : switch_table()) {
        EXPECT_NE(help.find(std::string(topic_title(spec.topic)) + ":"), std::string::npos);
        const std::string line = summary_line(help, spec);
        EXPECT_NE(line.find(spec.summary), std::string::npos) << spec.spelling;
        // The mark follows the summary, on the next line when the summary is long.
        const std::size_t at = help.find(line + "\n");
        const std::string next = help.substr(at + line.size() + 1, 60);
        const std::size_t mark = next.find("(not implemented yet)");
        const bool marked = line.ends_with("(not implemented yet)") ||
                            (mark != std::string::npos && mark == next.find_first_not_of(' '));
        EXPECT_EQ(marked, spec.status == Status::NotYet) << spec.spelling;
    }
    EXPECT_NE(help.find("--output FILE"), std::string::npos);
    EXPECT_NE(help.find("-Dl (or -DI)"), std::string::npos);
    EXPECT_TRUE(has_line_with(help, "multiplier > 0", "e.g. -m2.0"));
}

TEST(SwitchHelp, Synopses) {
    auto of = [](std::string_view spelling) {
        for (const SwitchSpec& spec : switch_table()) {
            if (spec.spelling == spelling) {
                return synopsis(spec) + " | " + argument_text(spec);
            }
        }
        return std::string("missing");
    };
    EXPECT_EQ(of("-Dd"), "-Dd | ");
    EXPECT_EQ(of("-Stg"), "-Stg<m> | m >= 0.000001, attached or separate");
    EXPECT_EQ(of("-A"),
              "-A<distance>,<constant> | distance > 0, constant > 0, attached or separate");
    EXPECT_EQ(of("-Wc"), "-Wc <angle> | angle in (0, pi], attached or separate");
    EXPECT_EQ(of("-L"), "-L<line> | line from 0 to 1000000, attached or separate");
    EXPECT_EQ(
        of("-Xp"),
        "-Xp<probability>,<variance> | probability in (0, 1), variance > 0, attached or separate");
    EXPECT_EQ(of("--output"), "--output FILE | ");
    EXPECT_EQ(of("--threads"), "--threads N | N from 0 to 1024");
}

TEST(SwitchHelp, Version) {
    EXPECT_EQ(version_text(), "rt 0.1.0 (CMU RayTracer 6.0 reimplementation)");
}

TEST(SwitchHelp, RangesDescribeThemselves) {
    EXPECT_EQ((Range{0.0, 0.0, true, false, false}.describe()), "> 0");
    EXPECT_EQ((Range{0.0, 0.0, false, false, false}.describe()), ">= 0");
    EXPECT_EQ((Range{0.0, 1.0, true, true, true}.describe()), "in (0, 1)");
    EXPECT_EQ((Range{1.0, 20.0, false, false, true}.describe()), "from 1 to 20");
    EXPECT_TRUE((Range{0.0, 1.0, true, true, true}.contains(0.5)));
    EXPECT_FALSE((Range{0.0, 1.0, true, true, true}.contains(1.0)));
    EXPECT_TRUE((Range{0.0, 0.0, false, false, false}.contains(1e300)));
}

}  // namespace
}  // namespace rt
