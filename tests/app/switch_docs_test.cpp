// docs/switches.md is generated from the switch table; this keeps the committed copy current.
#include <filesystem>
#include <string>

#include "rt/app/help.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt {
namespace {

TEST(SwitchDocs, CommittedMarkdownMatchesTheTable) {
    const std::filesystem::path path = test::source_dir() / "docs" / "switches.md";
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    EXPECT_TRUE(test::read_text(path) == switches_markdown())
        << "docs/switches.md is out of date: regenerate with build/bin/gen_switch_docs "
           "docs/switches.md";
}

TEST(SwitchDocs, MarkdownHasEverySwitch) {
    const std::string markdown = switches_markdown();
    for (const SwitchSpec& spec : switch_table()) {
        EXPECT_NE(markdown.find("| `" + synopsis(spec) + "`"), std::string::npos) << spec.spelling;
    }
}

}  // namespace
}  // namespace rt
